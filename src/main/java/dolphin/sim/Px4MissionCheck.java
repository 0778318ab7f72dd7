package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import com.MAVLink.enums.MAV_MISSION_RESULT;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.Fence;
import dolphin.mission.model.MissionItem;
import dolphin.mission.transfer.StoredItems;
import java.util.List;
import java.util.OptionalInt;
import java.util.Set;

/**
 * What PX4 takes of a mission (PX4-Autopilot's mavlink_mission.cpp and FeasibilityChecker.cpp): at
 * upload, a command with a position in a global frame (GLOBAL or GLOBAL_RELATIVE_ALT, float or int)
 * and one without in MAV_FRAME_MISSION; any other command in either is UNSUPPORTED, any other frame
 * UNSUPPORTED_FRAME. What a download gives back of an item, and whether the stored mission is
 * feasible: only the commands the feasibility check allows, and on a fixed wing or a VTOL a landing
 * (MIS_TKO_LAND_REQ 2).
 */
final class Px4MissionCheck {

    /** parse_mavlink_mission_item's commands in a global frame. */
    static final Set<Integer> WITH_POSITION = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM,
            MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_LAND, MAV_CMD.MAV_CMD_NAV_TAKEOFF,
            MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, MAV_CMD.MAV_CMD_NAV_ROI, MAV_CMD.MAV_CMD_DO_SET_ROI,
            MAV_CMD.MAV_CMD_DO_SET_ROI_LOCATION, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, MAV_CMD.MAV_CMD_NAV_VTOL_LAND,
            MAV_CMD.MAV_CMD_CONDITION_GATE, MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM);

    /** parse_mavlink_mission_item's commands in MAV_FRAME_MISSION. */
    static final Set<Integer> WITHOUT_POSITION = Set.of(MAV_CMD.MAV_CMD_DO_JUMP, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED,
            MAV_CMD.MAV_CMD_DO_SET_HOME, MAV_CMD.MAV_CMD_DO_LAND_START, MAV_CMD.MAV_CMD_DO_VTOL_TRANSITION,
            MAV_CMD.MAV_CMD_DO_WINCH, MAV_CMD.MAV_CMD_DO_GRIPPER, MAV_CMD.MAV_CMD_DO_SET_ACTUATOR,
            MAV_CMD.MAV_CMD_DO_TRIGGER_CONTROL, MAV_CMD.MAV_CMD_DO_DIGICAM_CONTROL, MAV_CMD.MAV_CMD_DO_DIGICAM_CONFIGURE,
            MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_INTERVAL, MAV_CMD.MAV_CMD_OBLIQUE_SURVEY,
            MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE, MAV_CMD.MAV_CMD_VIDEO_START_CAPTURE,
            MAV_CMD.MAV_CMD_VIDEO_STOP_CAPTURE, MAV_CMD.MAV_CMD_DO_CONTROL_VIDEO, MAV_CMD.MAV_CMD_SET_CAMERA_MODE,
            MAV_CMD.MAV_CMD_SET_CAMERA_ZOOM, MAV_CMD.MAV_CMD_SET_CAMERA_FOCUS, MAV_CMD.MAV_CMD_SET_CAMERA_SOURCE,
            MAV_CMD.MAV_CMD_DO_MOUNT_CONFIGURE, MAV_CMD.MAV_CMD_DO_MOUNT_CONTROL, MAV_CMD.MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW,
            MAV_CMD.MAV_CMD_DO_GIMBAL_MANAGER_CONFIGURE, MAV_CMD.MAV_CMD_NAV_DELAY, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH,
            MAV_CMD.MAV_CMD_DO_SET_ROI, MAV_CMD.MAV_CMD_DO_SET_ROI_WPNEXT_OFFSET, MAV_CMD.MAV_CMD_DO_SET_ROI_NONE,
            MAV_CMD.MAV_CMD_CONDITION_DELAY, MAV_CMD.MAV_CMD_CONDITION_DISTANCE);

    /** Uploaded, but missing from FeasibilityChecker::checkMissionItemValidity: the mission is not valid. */
    static final Set<Integer> INFEASIBLE = Set.of(MAV_CMD.MAV_CMD_CONDITION_DELAY, MAV_CMD.MAV_CMD_CONDITION_DISTANCE);

    private static final Set<Integer> GLOBAL = Set.of(MAV_FRAME.MAV_FRAME_GLOBAL, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT,
            MAV_FRAME.MAV_FRAME_GLOBAL_INT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT);

    private static final Set<Integer> LANDINGS = Set.of(MAV_CMD.MAV_CMD_NAV_LAND, MAV_CMD.MAV_CMD_NAV_VTOL_LAND);

    private Px4MissionCheck() {
    }

    /** The MISSION_ACK result for an uploaded item. */
    static int result(MissionItem item) {
        if (item.frame() == MAV_FRAME.MAV_FRAME_MISSION) {
            return WITHOUT_POSITION.contains(item.command()) ? MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
                    : MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED;
        }
        if (GLOBAL.contains(item.frame())) {
            return WITH_POSITION.contains(item.command()) ? MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
                    : MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED;
        }
        return MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED_FRAME;
    }

    /**
     * format_mavlink_mission_item: an item without a position comes back whole; of one with a position
     * only what the navigator keeps: a waypoint's pass radius (param3), a take-off's pitch and a landing's
     * abort altitude (param1) come back 0, a timed loiter's param4 as its cross-track flag, an ROI and an
     * arm or disarm with params 1 to 4 at 0.
     */
    static MissionItem stored(MissionItem i) {
        if (i.frame() == MAV_FRAME.MAV_FRAME_MISSION) {
            return i;
        }
        float[] p = {i.param1(), i.param2(), i.param3(), i.param4()};
        switch (i.command()) {
            case MAV_CMD.MAV_CMD_NAV_WAYPOINT -> p[2] = 0;
            case MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_NAV_LAND -> p[0] = 0;
            case MAV_CMD.MAV_CMD_NAV_LOITER_TIME -> p[3] = p[3] > 0 ? 1 : 0;
            case MAV_CMD.MAV_CMD_NAV_ROI, MAV_CMD.MAV_CMD_DO_SET_ROI, MAV_CMD.MAV_CMD_DO_SET_ROI_LOCATION,
                 MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM -> p = new float[4];
            default -> {
                return i;
            }
        }
        return new MissionItem(i.seq(), i.command(), i.frame(), p[0], p[1], p[2], p[3], i.x(), i.y(), i.z(), i.autocontinue());
    }

    /**
     * The first item with a position outside the fence (outside every inclusion region or inside an
     * exclusion one), as PX4's feasibility check numbers it: its seq on PX4 plus one, which is the
     * runtime's seq. Empty without a fence or when every item is inside.
     */
    static OptionalInt outsideFence(List<MissionItem> items, Fence fence) {
        if (fence.isEmpty()) {
            return OptionalInt.empty();
        }
        return items.subList(1, items.size()).stream()
                .filter(i -> StoredItems.POSITIONAL.contains(i.command()) && fence.breachedBy(i.position()).isPresent())
                .mapToInt(MissionItem::seq).findFirst();
    }

    /** Whether PX4 finds the stored mission (home first) feasible: no item it does not fly, and a landing on a fixed wing or VTOL. */
    static boolean feasible(List<MissionItem> items, VehicleFamily family) {
        List<MissionItem> real = items.subList(1, items.size());
        if (real.stream().anyMatch(i -> INFEASIBLE.contains(i.command()))) {
            return false;
        }
        boolean landingRequired = family == VehicleFamily.PLANE || family == VehicleFamily.VTOL;
        return !landingRequired || real.stream().anyMatch(i -> LANDINGS.contains(i.command()));
    }
}
