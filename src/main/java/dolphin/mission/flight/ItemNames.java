package dolphin.mission.flight;

import com.MAVLink.enums.MAV_LANDED_STATE;
import dolphin.mavlink.EnumNames;
import dolphin.mavlink.VehicleState;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Locale;

/** How the executor's lines and errors name a mission's items and what the vehicle last reported. */
final class ItemNames {

    private final List<MissionItem> items;

    ItemNames(List<MissionItem> items) {
        this.items = List.copyOf(items);
    }

    int last() {
        return items.size() - 1;
    }

    MissionItem get(int seq) {
        return items.get(Math.max(0, Math.min(seq, last())));
    }

    /** "item 3 of 20 (NAV_WAYPOINT)". */
    String item(int seq) {
        return "item " + seq + " of " + last() + " (" + get(seq).commandName() + ")";
    }

    /** What the vehicle last reported, for errors: ": armed, AUTO, landed state IN_AIR, 20.0 m above home, last text '...'". */
    static String where(VehicleState s) {
        List<String> texts = s.statusTexts();
        return whereWithout(s) + (texts.isEmpty() ? "" : ", last text '" + texts.get(texts.size() - 1) + "'");
    }

    /** As {@link #where}, without the last text: for errors that quote the vehicle's words themselves. */
    static String whereWithout(VehicleState s) {
        StringBuilder b = new StringBuilder(": ").append(s.armed() ? "armed" : "disarmed").append(", ").append(s.modeName());
        b.append(", landed state ").append(EnumNames.name(MAV_LANDED_STATE.class, "MAV_LANDED_STATE_", s.landedState()));
        if (s.position() != null) {
            b.append(String.format(Locale.ROOT, ", %.1f m above home", s.relativeAlt()));
        }
        return b.toString();
    }
}
