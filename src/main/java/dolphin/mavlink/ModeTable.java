package dolphin.mavlink;

import java.util.Locale;
import java.util.Map;
import java.util.OptionalLong;

/** The flight modes of one autopilot and vehicle family: HEARTBEAT custom_mode to name, and back. */
public record ModeTable(Map<Long, String> names) {

    public static final ModeTable NONE = new ModeTable(Map.of());

    public ModeTable {
        names = Map.copyOf(names);
    }

    /** The mode's name, or "mode N" when the table has none (a mode newer than our bindings, or an unknown autopilot). */
    public String name(long customMode) {
        String n = names.get(customMode);
        return n != null ? n : "mode " + customMode;
    }

    /** The custom_mode of a mode name, whatever its case; empty when the table has no such mode. */
    public OptionalLong number(String name) {
        String wanted = name.toUpperCase(Locale.ROOT);
        return names.entrySet().stream().filter(e -> e.getValue().equals(wanted)).mapToLong(Map.Entry::getKey).findFirst();
    }

    public boolean contains(long customMode) {
        return names.containsKey(customMode);
    }
}
