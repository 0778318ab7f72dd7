package dolphin.sensor;

import com.MAVLink.Messages.MAVLinkMessage;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * What one vehicle's sensors last said, and the last message of each kind from each of its components
 * (for {@code telemetry(v, 'VFR_HUD', 'groundspeed')}). The communications thread writes; script, web
 * and status threads read immutable {@link Reading}s, so nobody sees half a reading.
 */
public final class VehicleReadings {

    /** The last message of one kind from one component, and when it came. */
    public record LastMessage(MAVLinkMessage message, int component, long nanos) {
    }

    private static final Comparator<Reading> ORDER = Comparator.comparing(Reading::name).thenComparingInt(Reading::component);

    private final Map<String, Map<Integer, Reading>> byName = new ConcurrentHashMap<>();
    private final Map<Long, LastMessage> messages = new ConcurrentHashMap<>();

    void put(Reading r) {
        byName.computeIfAbsent(r.name(), n -> new ConcurrentHashMap<>()).put(r.component(), r);
    }

    void received(int component, MAVLinkMessage message, long nanos) {
        messages.put(key(component, message.msgid), new LastMessage(message, component, nanos));
    }

    /** The latest reading of that name from each component that sent one, by component id. */
    public List<Reading> named(String name) {
        Map<Integer, Reading> byComponent = byName.get(name);
        return byComponent == null ? List.of() : byComponent.values().stream().sorted(ORDER).toList();
    }

    /** The latest reading of every name and component, by name then component. */
    public List<Reading> all() {
        return byName.values().stream().flatMap(m -> m.values().stream()).sorted(ORDER).toList();
    }

    /** The last message with that id from that component, or null. */
    public LastMessage message(int component, int msgid) {
        return messages.get(key(component, msgid));
    }

    private static long key(int component, int msgid) {
        return ((long) component << 32) | msgid;
    }
}
