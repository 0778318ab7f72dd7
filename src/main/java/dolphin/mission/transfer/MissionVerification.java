package dolphin.mission.transfer;

import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.mavlink.Autopilot;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * Compares the items sent with those downloaded back, skipping item 0 (ArduPilot replaces it with
 * its home), as ArduPilot's autotest does (check_mission_upload_download): the command, param1
 * (NaN equal to NaN), x and y exactly (degE7) and z within 1 cm. ArduPilot stores only what each
 * command uses, so params 2 to 4 may come back 0; it keeps a location's altitude reference but not
 * its frame, so a GLOBAL_INT item comes back GLOBAL: frames are compared by altitude reference,
 * for items with a position only.
 *
 * <p>A fence or rally points have no home: every item is compared. ArduPilot keeps of a fence item
 * only its command, param1 (vertex count or radius; none for the return point) and position, and of
 * a rally point its position, altitude reference and height as whole metres (docs/airspace.md): the
 * rest is not compared, and a rally point's height may come back up to 1 m off.
 *
 * <p>PX4 keeps every param of a command without a position (MAV_FRAME_MISSION), but of one with a
 * position only the params its navigator uses (MavlinkMissionManager::format_mavlink_mission_item):
 * param1 only of a waypoint (its hold time), a timed loiter and a loiter to altitude. The runtime
 * numbers a PX4 mission with home as item 0 too ({@link AutopilotLists}), so item 0 is skipped alike.
 */
public final class MissionVerification {

    /** How far a downloaded z may be from the one sent, in metres (the vehicle may store it with less precision). */
    public static final double Z_TOLERANCE = 0.01;

    private MissionVerification() {
    }

    /** The commands with a position whose param1 PX4 keeps. */
    private static final Set<Integer> PX4_PARAM1 = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_TIME,
            MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT);

    /** The first difference, e.g. "item 2 (NAV_WAYPOINT): z sent 20.0, vehicle has 25.0"; empty when they match. */
    public static Optional<String> firstDifference(List<MissionItem> sent, List<MissionItem> downloaded) {
        return firstDifference(MissionType.MISSION, sent, downloaded);
    }

    /** The same for a mission, a fence or rally points held by ArduPilot. */
    public static Optional<String> firstDifference(MissionType type, List<MissionItem> sent, List<MissionItem> downloaded) {
        return firstDifference(Autopilot.ARDUPILOT, type, sent, downloaded);
    }

    /** The same for a list held by the autopilot. */
    public static Optional<String> firstDifference(Autopilot autopilot, MissionType type, List<MissionItem> sent,
                                                   List<MissionItem> downloaded) {
        if (sent.size() != downloaded.size()) {
            return Optional.of("the vehicle has " + downloaded.size() + " items" + (type.hasHome() ? " (home included), " : ", ")
                    + sent.size() + " were sent");
        }
        for (int i = type.hasHome() ? 1 : 0; i < sent.size(); i++) {
            MissionItem s = sent.get(i);
            MissionItem d = downloaded.get(i);
            String diff = switch (type) {
                case MISSION -> difference(s, d, keepsParam1(autopilot, s));
                case FENCE -> fenceDifference(s, d);
                case RALLY -> rallyDifference(s, d);
            };
            if (diff != null) {
                return Optional.of("item " + i + " (" + s.commandName() + "): " + diff);
            }
        }
        return Optional.empty();
    }

    private static String fenceDifference(MissionItem s, MissionItem d) {
        if (s.command() != d.command()) {
            return "command sent " + s.commandName() + ", vehicle has " + d.commandName();
        }
        if (s.command() != MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT && s.param1() != d.param1()) {
            return "param1 sent " + s.param1() + ", vehicle has " + d.param1();
        }
        return position(s, d);
    }

    private static String rallyDifference(MissionItem s, MissionItem d) {
        if (s.command() != d.command()) {
            return "command sent " + s.commandName() + ", vehicle has " + d.commandName();
        }
        if (MissionItem.altitudeReference(s.frame()) != MissionItem.altitudeReference(d.frame())) {
            return "frame sent " + s.frameName() + ", vehicle has " + d.frameName();
        }
        if (!(Math.abs(s.z() - d.z()) < 1)) {
            return "z sent " + s.z() + ", vehicle has " + d.z();
        }
        return position(s, d);
    }

    private static String position(MissionItem s, MissionItem d) {
        if (s.x() != d.x()) {
            return "x sent " + s.x() + ", vehicle has " + d.x();
        }
        if (s.y() != d.y()) {
            return "y sent " + s.y() + ", vehicle has " + d.y();
        }
        return null;
    }

    private static boolean keepsParam1(Autopilot autopilot, MissionItem item) {
        return autopilot != Autopilot.PX4 || item.frame() == MAV_FRAME.MAV_FRAME_MISSION || PX4_PARAM1.contains(item.command());
    }

    private static String difference(MissionItem s, MissionItem d, boolean param1Kept) {
        if (s.command() != d.command()) {
            return "command sent " + s.commandName() + ", vehicle has " + d.commandName();
        }
        if (s.frame() != MAV_FRAME.MAV_FRAME_MISSION
                && MissionItem.altitudeReference(s.frame()) != MissionItem.altitudeReference(d.frame())) {
            return "frame sent " + s.frameName() + ", vehicle has " + d.frameName();
        }
        if (param1Kept && Float.compare(s.param1(), d.param1()) != 0 && !(s.param1() == d.param1())) {
            return "param1 sent " + s.param1() + ", vehicle has " + d.param1();
        }
        String where = position(s, d);
        if (where != null) {
            return where;
        }
        boolean bothNaN = Float.isNaN(s.z()) && Float.isNaN(d.z());
        if (!bothNaN && !(Math.abs(s.z() - d.z()) <= Z_TOLERANCE)) {
            return "z sent " + s.z() + ", vehicle has " + d.z();
        }
        return null;
    }
}
