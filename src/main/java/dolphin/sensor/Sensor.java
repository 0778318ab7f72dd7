package dolphin.sensor;

import com.MAVLink.Messages.MAVLinkMessage;
import java.time.Duration;
import java.util.Set;

/**
 * Turns MAVLink messages from a vehicle into named readings that scripts read with
 * {@code sensor(v, 'NAME')}: the extensible sensor API (docs/sensors.md). A user's sensor is a class
 * with a public no-argument constructor, listed in {@code META-INF/services/dolphin.sensor.Sensor}
 * of a jar on the class path, or handed to a script's {@code useSensor}. Its methods run on the
 * communications thread: {@link #read} must be quick and must not block; an exception it throws is
 * logged and the message skipped.
 */
public interface Sensor {

    /** How long a reading counts as current unless the sensor says otherwise. */
    Duration DEFAULT_FRESHNESS = Duration.ofSeconds(5);

    /** The message classes it reads, from the generated bindings (e.g. {@code msg_distance_sensor.class}). */
    Set<Class<? extends MAVLinkMessage>> messages();

    /**
     * Puts the readings found in one message into {@code out}; called for each message of
     * {@link #messages()} from any component of the vehicle.
     */
    void read(MAVLinkMessage message, ReadingSink out);

    /** The names it gives readings, for {@code dolphin check}; empty when they come from the messages (NAMED_VALUE). */
    default Set<String> names() {
        return Set.of();
    }

    /** How long after it arrived a reading is still the sensor's value; older is stale, an error to read. */
    default Duration freshness() {
        return DEFAULT_FRESHNESS;
    }
}
