package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import java.util.Map;

/** The names AP_Mission gives mission commands in its "Mission: 3 WP" texts (Mission_Command::type). */
final class CommandNames {

    private static final Map<Integer, String> NAMES = Map.ofEntries(
            Map.entry(MAV_CMD.MAV_CMD_NAV_WAYPOINT, "WP"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, "SplineWP"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, "RTL"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, "LoitUnlim"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_LOITER_TIME, "LoitTime"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, "LoitTurns"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, "LoitAltitude"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_TAKEOFF, "Takeoff"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_LAND, "Land"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, "VTOLTakeoff"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_VTOL_LAND, "VTOLLand"),
            Map.entry(MAV_CMD.MAV_CMD_DO_VTOL_TRANSITION, "VTOLTransition"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_CONTINUE_AND_CHANGE_ALT, "ContinueAndChangeAlt"),
            Map.entry(MAV_CMD.MAV_CMD_NAV_DELAY, "Delay"),
            Map.entry(MAV_CMD.MAV_CMD_CONDITION_DELAY, "CondDelay"),
            Map.entry(MAV_CMD.MAV_CMD_CONDITION_DISTANCE, "CondDist"),
            Map.entry(MAV_CMD.MAV_CMD_CONDITION_YAW, "CondYaw"),
            Map.entry(MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, "ChangeSpeed"),
            Map.entry(MAV_CMD.MAV_CMD_DO_SET_HOME, "SetHome"),
            Map.entry(MAV_CMD.MAV_CMD_DO_SET_SERVO, "SetServo"),
            Map.entry(MAV_CMD.MAV_CMD_DO_SET_RELAY, "SetRelay"),
            Map.entry(MAV_CMD.MAV_CMD_DO_REPEAT_SERVO, "RepeatServo"),
            Map.entry(MAV_CMD.MAV_CMD_DO_REPEAT_RELAY, "RepeatRelay"),
            Map.entry(MAV_CMD.MAV_CMD_DO_DIGICAM_CONFIGURE, "DigiCamCfg"),
            Map.entry(MAV_CMD.MAV_CMD_DO_DIGICAM_CONTROL, "DigiCamCtrl"),
            Map.entry(MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, "SetCamTrigDst"),
            Map.entry(MAV_CMD.MAV_CMD_DO_SET_ROI, "SetROI"),
            Map.entry(MAV_CMD.MAV_CMD_DO_LAND_START, "LandStart"),
            Map.entry(MAV_CMD.MAV_CMD_DO_GRIPPER, "Gripper"),
            Map.entry(MAV_CMD.MAV_CMD_DO_PARACHUTE, "Parachute"),
            Map.entry(MAV_CMD.MAV_CMD_DO_MOUNT_CONTROL, "MountControl"),
            Map.entry(MAV_CMD.MAV_CMD_DO_JUMP, "Jump"),
            Map.entry(MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, "ImageStartCapture"),
            Map.entry(MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE, "ImageStopCapture"));

    private CommandNames() {
    }

    /** "?" for a command without a name here, as AP_Mission answers one it does not name. */
    static String of(int command) {
        return NAMES.getOrDefault(command, "?");
    }
}
