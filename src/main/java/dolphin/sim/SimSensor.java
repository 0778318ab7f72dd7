package dolphin.sim;

import java.util.Objects;

/**
 * A sensor some vehicles of the fleet carry: it reads {@code field} where the vehicle is and
 * sends the value as NAMED_VALUE_FLOAT {@code name}, as an ArduPilot Lua script's
 * gcs:send_named_float does.
 */
public record SimSensor(String name, SimField field, SysidSet vehicles) {

    /** NAMED_VALUE_FLOAT's name is char[10]. */
    public static final int MAX_NAME = dolphin.sensor.NamedValues.MAX_NAME;

    public SimSensor {
        Objects.requireNonNull(field, "field");
        Objects.requireNonNull(vehicles, "vehicles");
        if (name == null || name.isEmpty() || name.length() > MAX_NAME || !name.chars().allMatch(c -> c > ' ' && c < 127)) {
            throw new IllegalArgumentException("a sensor name must be 1 to " + MAX_NAME
                    + " printable ASCII characters without spaces (NAMED_VALUE_FLOAT's name is char[10]), got '" + name + "'");
        }
    }

    /** Carried by every vehicle. */
    public SimSensor(String name, SimField field) {
        this(name, field, SysidSet.ALL);
    }
}
