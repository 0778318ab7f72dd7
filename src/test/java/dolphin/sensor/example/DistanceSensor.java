package dolphin.sensor.example;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_distance_sensor;
import com.MAVLink.enums.MAV_SENSOR_ORIENTATION;
import dolphin.sensor.ReadingSink;
import dolphin.sensor.Sensor;
import java.time.Duration;
import java.util.Set;

/**
 * The example of docs/sensors.md: a rangefinder's DISTANCE_SENSOR (centimetres) as DISTANCE_DOWN or
 * DISTANCE_FWD in metres. Installed through META-INF/services/dolphin.sensor.Sensor.
 */
public final class DistanceSensor implements Sensor {

    @Override
    public Set<Class<? extends MAVLinkMessage>> messages() {
        return Set.of(msg_distance_sensor.class);
    }

    @Override
    public void read(MAVLinkMessage message, ReadingSink out) {
        msg_distance_sensor m = (msg_distance_sensor) message;
        String name = switch (m.orientation) {
            case MAV_SENSOR_ORIENTATION.MAV_SENSOR_ROTATION_PITCH_270 -> "DISTANCE_DOWN";
            case MAV_SENSOR_ORIENTATION.MAV_SENSOR_ROTATION_NONE -> "DISTANCE_FWD";
            default -> null;
        };
        // the sensor says how far it can measure: a distance outside that is no distance
        if (name != null && m.current_distance >= m.min_distance && m.current_distance <= m.max_distance) {
            out.put(name, m.current_distance / 100.0, "m");
        }
    }

    @Override
    public Set<String> names() {
        return Set.of("DISTANCE_DOWN", "DISTANCE_FWD");
    }

    @Override
    public Duration freshness() {
        return Duration.ofSeconds(1);
    }
}
