package dolphin.mission.transfer;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import dolphin.mavlink.Autopilot;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import java.util.ArrayList;
import java.util.List;

/**
 * A list as the runtime writes it and as the vehicle's autopilot holds it. The runtime numbers a
 * mission with home as item 0; an autopilot that keeps no home item (PX4) numbers its first item 0:
 * uploads leave item 0 out and renumber the rest, DO_JUMP targets with them, and downloads put the
 * vehicle's home back in front. PX4's return reads a rally point's frame as sent, and only
 * MAV_FRAME_GLOBAL and GLOBAL_RELATIVE_ALT ("RTL: unsupported MAV_FRAME" otherwise, on its SITL):
 * its rally points go in those. Every list of ArduPilot passes unchanged.
 */
final class AutopilotLists {

    private AutopilotLists() {
    }

    /** The number of items the runtime's list has before the vehicle's first: 1 when home is left out. */
    static int offset(Autopilot autopilot, MissionType type) {
        return type == MissionType.MISSION && !autopilot.homeItem() ? 1 : 0;
    }

    /** The items as the vehicle numbers them. */
    static List<MissionItem> toVehicle(Autopilot autopilot, MissionType type, List<MissionItem> items) {
        if (type == MissionType.RALLY && autopilot == Autopilot.PX4) {
            return items.stream().map(i -> new MissionItem(i.seq(), i.command(), MissionItem.altitudeReference(i.frame()), i.param1(),
                    i.param2(), i.param3(), i.param4(), i.x(), i.y(), i.z(), i.autocontinue())).toList();
        }
        int offset = offset(autopilot, type);
        if (offset == 0 || items.isEmpty()) {
            return items;
        }
        List<MissionItem> out = new ArrayList<>(items.size() - offset);
        for (MissionItem i : items.subList(offset, items.size())) {
            out.add(renumbered(i, -offset));
        }
        return out;
    }

    /**
     * The vehicle's items as the runtime numbers them.
     *
     * @param home the vehicle's home, item 0 of the result; null when it has not said (item 0 then all zeros, as an unset home)
     */
    static List<MissionItem> fromVehicle(Autopilot autopilot, MissionType type, List<MissionItem> items, Position home) {
        int offset = offset(autopilot, type);
        if (offset == 0) {
            return items;
        }
        List<MissionItem> out = new ArrayList<>(items.size() + 1);
        out.add(home != null ? StoredItems.home(home) : StoredItems.UNSET_HOME);
        for (MissionItem i : items) {
            out.add(renumbered(i, offset));
        }
        return out;
    }

    private static MissionItem renumbered(MissionItem i, int by) {
        float p1 = i.command() == MAV_CMD.MAV_CMD_DO_JUMP ? i.param1() + by : i.param1();
        return new MissionItem(i.seq() + by, i.command(), i.frame(), p1, i.param2(), i.param3(), i.param4(), i.x(), i.y(), i.z(),
                i.autocontinue());
    }
}
