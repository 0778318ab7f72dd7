package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import com.MAVLink.enums.MAV_MISSION_RESULT;
import dolphin.mission.model.MissionItem;
import dolphin.mission.transfer.StoredItems;
import java.util.Map;
import java.util.Set;

/**
 * The checks ArduPilot makes on each uploaded item (AP_Mission::mavlink_int_to_mission_cmd), in its
 * order and with its MAV_MISSION_RESULT codes: param1 to param4 must be finite, NaN allowed only
 * where {@link #NAN_ALLOWED} says (AP_Mission::sanity_check_params, before the command is even
 * looked at); commands it does not know (DO_CHANGE_ALTITUDE, DO_TRIGGER_CONTROL and
 * CONDITION_CHANGE_ALT among them) are UNSUPPORTED; a waypoint's hold time (param1) must fit 0 to
 * 65535 s, but on ArduPlane, which ignores it and refuses SPLINE_WAYPOINT (UNSUPPORTED); commands
 * with a position accept only the global frames (and MISSION); latitude, longitude and altitude
 * must be sane.
 */
final class MissionCheck {

    /** Commands without a location that ArduPilot stores in a mission. */
    static final Set<Integer> OTHERS = Set.of(MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, MAV_CMD.MAV_CMD_NAV_DELAY,
            MAV_CMD.MAV_CMD_CONDITION_DELAY, MAV_CMD.MAV_CMD_CONDITION_DISTANCE,
            MAV_CMD.MAV_CMD_CONDITION_YAW, MAV_CMD.MAV_CMD_DO_JUMP, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED,
            MAV_CMD.MAV_CMD_DO_SET_RELAY, MAV_CMD.MAV_CMD_DO_REPEAT_RELAY, MAV_CMD.MAV_CMD_DO_SET_SERVO,
            MAV_CMD.MAV_CMD_DO_REPEAT_SERVO, MAV_CMD.MAV_CMD_DO_DIGICAM_CONFIGURE, MAV_CMD.MAV_CMD_DO_DIGICAM_CONTROL,
            MAV_CMD.MAV_CMD_DO_MOUNT_CONTROL, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, MAV_CMD.MAV_CMD_DO_GRIPPER,
            MAV_CMD.MAV_CMD_DO_SET_ROI_NONE, MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE,
            MAV_CMD.MAV_CMD_VIDEO_START_CAPTURE, MAV_CMD.MAV_CMD_VIDEO_STOP_CAPTURE, MAV_CMD.MAV_CMD_DO_PARACHUTE,
            MAV_CMD.MAV_CMD_DO_VTOL_TRANSITION);

    static final Set<Integer> GLOBAL_FRAMES = Set.of(MAV_FRAME.MAV_FRAME_MISSION, MAV_FRAME.MAV_FRAME_GLOBAL,
            MAV_FRAME.MAV_FRAME_GLOBAL_INT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT,
            MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT,
            MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT);

    /**
     * The params (bit 0 = param1) in which AP_Mission::sanity_check_params lets a command have NaN;
     * every other command may have none.
     */
    static final Map<Integer, Integer> NAN_ALLOWED = Map.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0b1000,
            MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, 0b1000, MAV_CMD.MAV_CMD_NAV_LAND, 0b1000,
            MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0b1000, MAV_CMD.MAV_CMD_NAV_ARC_WAYPOINT, 0b1110,
            MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, 0b1000, MAV_CMD.MAV_CMD_NAV_VTOL_LAND, 0b1100);

    /** The MAV_MISSION_RESULT of a bad param1 to param4, in order. */
    private static final int[] INVALID_PARAM = {MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1,
            MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM2, MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM3,
            MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM4};

    /** ArduPilot's LOCATION_ALT_MAX_M: heights beyond it do not fit its Location. */
    static final double ALT_MAX_METRES = 83_000;

    private MissionCheck() {
    }

    /**
     * MAV_MISSION_ACCEPTED, or the error the vehicle answers the item with; {@code plane} for
     * ArduPlane, whose build of AP_Mission converts some commands differently.
     */
    static int result(MissionItem item, boolean plane) {
        int params = params(item);
        if (params != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
            return params;
        }
        if (!StoredItems.POSITIONAL.contains(item.command())) {
            return OTHERS.contains(item.command()) ? MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
                    : MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED;
        }
        int command = plane ? planeCommand(item) : holdTime(item);
        if (command != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
            return command;
        }
        int position = position(item);
        if (position != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
            return position;
        }
        if (!Float.isFinite(item.z()) || Math.abs(item.z()) >= ALT_MAX_METRES) {
            return MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM7;
        }
        return MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
    }

    /** ArduPlane has no spline waypoints. */
    private static int planeCommand(MissionItem item) {
        return item.command() == MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT ? MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
                : MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
    }

    /** The other vehicles store a waypoint's hold time (param1) in 16 bits. */
    private static int holdTime(MissionItem item) {
        boolean fits = item.command() != MAV_CMD.MAV_CMD_NAV_WAYPOINT || item.param1() >= 0 && item.param1() <= 0xffff;
        return fits ? MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED : MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1;
    }

    /** ACCEPTED, or INVALID_PARAM1 to 4 for the first of param1 to param4 that is infinite or a NaN not allowed there. */
    static int params(MissionItem item) {
        float[] params = {item.param1(), item.param2(), item.param3(), item.param4()};
        int nanAllowed = NAN_ALLOWED.getOrDefault(item.command(), 0);
        for (int i = 0; i < params.length; i++) {
            boolean nanRefused = Float.isNaN(params[i]) && (nanAllowed & (1 << i)) == 0;
            if (nanRefused || Float.isInfinite(params[i])) {
                return INVALID_PARAM[i];
            }
        }
        return MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
    }

    /** A global frame (or MISSION), latitude and longitude in range: ACCEPTED, or the error for the first that is not. */
    static int position(MissionItem item) {
        if (!GLOBAL_FRAMES.contains(item.frame())) {
            return MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED_FRAME;
        }
        if (Math.abs((long) item.x()) > 900_000_000L) {
            return MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM5_X;
        }
        if (Math.abs((long) item.y()) > 1_800_000_000L) {
            return MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM6_Y;
        }
        return MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
    }

    /**
     * A DO_JUMP whose target (p1) is item 0 or not below {@code count}: ArduPilot refuses it with
     * MAV_MISSION_ERROR (MissionItemProtocol_Waypoints, AP_Filesystem_Mission::finish_upload_mission).
     */
    static boolean jumpsNowhere(MissionItem item, int count) {
        if (item.command() != MAV_CMD.MAV_CMD_DO_JUMP) {
            return false;
        }
        int target = (int) item.param1() & 0xffff;
        return target == 0 || target >= count;
    }

    /** Whether the item's z is relative to home (relative and terrain frames, and MISSION). */
    static boolean relative(int frame) {
        return frame != MAV_FRAME.MAV_FRAME_GLOBAL && frame != MAV_FRAME.MAV_FRAME_GLOBAL_INT;
    }
}
