package dolphin.sitl

import dolphin.mavlink.mission.MissionItem

/**
 * Compares a mission as built with the one a vehicle sends back, the way ArduPilot's autotest does
 * (check_mission_upload_download): item 0 skipped (ArduPilot writes its home there), then per item
 * the command, param1 and, for items with a position, latitude and longitude (degE7, exact) and the
 * height within 1 cm (ArduPilot stores centimetres), with the height still above mean sea level
 * (MAV_FRAME_GLOBAL or GLOBAL_INT, never a relative frame). Other parameters and frames are not
 * compared: ArduPilot keeps only those its commands use (AP_Mission::mission_cmd_to_mavlink_int).
 */
final class SitlMissions {

    static final Set<Integer> AMSL_FRAMES = [com.MAVLink.enums.MAV_FRAME.MAV_FRAME_GLOBAL, MissionItem.GLOBAL_INT] as Set

    private SitlMissions() {
    }

    /** The first difference, e.g. "item 3 (NAV_WAYPOINT): z built 850.0, vehicle has 845.0"; null when they match. */
    static String difference(List<MissionItem> built, List<MissionItem> downloaded) {
        if (built.size() != downloaded.size()) {
            return "the vehicle has ${downloaded.size()} items (home included), ${built.size()} were built"
        }
        for (int i = 1; i < built.size(); i++) {
            MissionItem b = built[i]
            MissionItem d = downloaded[i]
            String diff = itemDifference(b, d)
            if (diff) {
                return "item ${i} (${b.commandName()}): ${diff}"
            }
        }
        null
    }

    private static String itemDifference(MissionItem b, MissionItem d) {
        if (b.command() != d.command()) {
            return "command built ${b.commandName()}, vehicle has ${d.commandName()}"
        }
        if (Math.abs(b.param1() - d.param1()) > 1e-3) {
            return "param1 built ${b.param1()}, vehicle has ${d.param1()}"
        }
        if (b.frame() != MissionItem.GLOBAL_INT) {
            return null
        }
        if (!(d.frame() in AMSL_FRAMES)) {
            return "frame built ${b.frameName()}, vehicle has ${d.frameName()}"
        }
        if (b.x() != d.x() || b.y() != d.y()) {
            return "position built ${b.x()}, ${b.y()}, vehicle has ${d.x()}, ${d.y()}"
        }
        Math.abs(b.z() - d.z()) > 0.01 ? "z built ${b.z()}, vehicle has ${d.z()}" : null
    }
}
