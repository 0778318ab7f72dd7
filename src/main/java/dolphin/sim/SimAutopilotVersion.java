package dolphin.sim;

import com.MAVLink.enums.MAV_PROTOCOL_CAPABILITY;
import com.MAVLink.standard.msg_autopilot_version;

/**
 * The AUTOPILOT_VERSION a simulated vehicle sends, as ArduPilot 4.8.0-dev SITL (64a9c78) does: the
 * capabilities of its firmware's GCS_MAVLINK_*::capabilities() with the common ones of
 * GCS_MAVLINK::capabilities() (float parameters, compass calibration, MAVLink 2, fence, rally, FTP
 * unless the vehicle has none), as SITL reported them with its default parameters (terrain on for
 * copter and plane; no flight termination for plane and rover, whose advanced failsafe is off).
 */
final class SimAutopilotVersion {

    /** GCS_MAVLINK::capabilities() on SITL, without FTP. */
    static final long COMMON = MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_PARAM_FLOAT
            | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_COMPASS_CALIBRATION
            | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_MAVLINK2
            | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_MISSION_FENCE
            | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_MISSION_RALLY;
    static final long PX4_CAPABILITIES = 0xe8ffL;
    /** 4.8.0, FIRMWARE_VERSION_TYPE_DEV (0): major, minor, patch, type, a byte each. */
    static final long FLIGHT_SW_VERSION = 4L << 24 | 8L << 16;

    private SimAutopilotVersion() {
    }

    static long capabilities(VehicleKind kind, boolean ftp) {
        long mission = MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_MISSION_FLOAT
                | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_MISSION_INT
                | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_SET_ATTITUDE_TARGET
                | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_SET_POSITION_TARGET_GLOBAL_INT;
        long own = switch (kind) {
            case COPTER, HELI -> MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_COMMAND_INT
                    | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_SET_POSITION_TARGET_LOCAL_NED
                    | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_FLIGHT_TERMINATION
                    | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_TERRAIN;
            case PLANE, QUADPLANE -> MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_COMMAND_INT
                    | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_TERRAIN;
            case ROVER, BOAT -> MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_COMMAND_INT
                    | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_SET_POSITION_TARGET_LOCAL_NED;
            case SUB -> MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_SET_POSITION_TARGET_LOCAL_NED
                    | MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_FLIGHT_TERMINATION;
        };
        return mission | own | COMMON | (ftp ? MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_FTP : 0);
    }

    /**
     * PX4's (mavlink_main.cpp; its SITL sent 0xe8ff): mission float and int, float parameters, COMMAND_INT,
     * parameters encoded bytewise, FTP unless the vehicle has none, attitude and local position targets,
     * flight termination, MAVLink 2, fence and rally; version 1.16.0, the release the measured build followed.
     */
    static msg_autopilot_version px4(boolean ftp) {
        msg_autopilot_version v = new msg_autopilot_version();
        v.capabilities = PX4_CAPABILITIES & ~(ftp ? 0 : MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_FTP);
        v.flight_sw_version = 1L << 24 | 16L << 16;
        return v;
    }

    static msg_autopilot_version message(VehicleKind kind, boolean ftp) {
        msg_autopilot_version v = new msg_autopilot_version();
        v.capabilities = capabilities(kind, ftp);
        v.flight_sw_version = FLIGHT_SW_VERSION;
        return v;
    }
}
