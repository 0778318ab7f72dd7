package dolphin.sim;

import com.MAVLink.common.msg_named_value_float;
import dolphin.core.Position;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The sensors one vehicle carries: every half second of clock time, armed or not, one
 * NAMED_VALUE_FLOAT per name with what they read where the vehicle is. Fields of one name add up,
 * so a plume can lie on a background gradient.
 */
final class SimSensors {

    static final long PERIOD = 500_000_000L;

    private final Map<String, List<SimField>> byName = new LinkedHashMap<>();
    private long nextDue;

    SimSensors(List<SimSensor> carried, long now) {
        for (SimSensor s : carried) {
            byName.computeIfAbsent(s.name(), n -> new ArrayList<>()).add(s.field());
        }
        this.nextDue = now;
    }

    /** The readings due at {@code now}, taken at {@code at}; none between two periods or without sensors. */
    List<msg_named_value_float> due(long now, Position at, long timeBootMillis) {
        if (byName.isEmpty() || now < nextDue) {
            return List.of();
        }
        nextDue = SimVehicle.nextOnGrid(nextDue, PERIOD, now);
        List<msg_named_value_float> readings = new ArrayList<>();
        byName.forEach((name, fields) -> {
            msg_named_value_float r = new msg_named_value_float();
            r.time_boot_ms = timeBootMillis;
            r.setName(name);
            r.value = (float) fields.stream().mapToDouble(f -> f.valueAt(at)).sum();
            readings.add(r);
        });
        return readings;
    }
}
