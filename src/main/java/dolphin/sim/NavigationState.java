package dolphin.sim;

import com.MAVLink.common.msg_gps_raw_int;
import com.MAVLink.enums.GPS_FIX_TYPE;
import dolphin.core.Position;
import dolphin.mission.model.MissionItem;

/**
 * The vehicle's GPS receiver and EKF once its warm-up is over, as GPS_RAW_INT, EKF_STATUS_REPORT and
 * the heartbeat report them: a 3D fix and SITL's flags of an EKF using GPS, until a {@link GpsLoss}
 * takes them away; EKF3's primary lane; and whether a failsafe is on, which ArduPilot reports as
 * MAV_STATE_CRITICAL (GCS_MAVLINK_Copter::vehicle_system_status, GCS_MAVLINK_Rover's).
 */
final class NavigationState {

    /** SITL's flags without a position, at boot: attitude, velocities and height, constant position mode. */
    static final int EKF_BOOTING = 167;
    /** SITL's flags once its EKF uses GPS: the horizontal position too, absolute and relative, and predicted. */
    static final int EKF_LOCATED = 831;

    /** SITL's GPS (SIM_GPS1_NUMSATS, the u-blox DOPs SIM_GPS_UBLOX sends: HDOP 1.21, VDOP 2.00). */
    private static final short SATELLITES = 10;
    private static final int HDOP = 121;
    private static final int VDOP = 200;
    /** AP_GPS's GPS_UNKNOWN_DOP, which is also MAVLink's "unknown". */
    private static final int UNKNOWN_DOP = 65535;

    private boolean gpsLost;
    private int ekfFlags = EKF_LOCATED;
    private boolean failsafe;
    private int primaryLane;

    /** The receiver is gone, as AP_GPS says once it has heard nothing for GPS_TIMEOUT_MS: its state cleared. */
    void gpsLost() {
        gpsLost = true;
    }

    void ekfFlags(int flags) {
        ekfFlags = flags;
    }

    /** EKF_STATUS_REPORT.flags, given whether the warm-up is over. */
    int ekfFlags(boolean located) {
        return located ? ekfFlags : EKF_BOOTING;
    }

    /** EKF3's primary lane (core): 0 until a lane switch. */
    int primaryLane() {
        return primaryLane;
    }

    void primaryLane(int lane) {
        primaryLane = lane;
    }

    void failsafe(boolean on) {
        failsafe = on;
    }

    boolean failsafe() {
        return failsafe;
    }

    /**
     * GPS_RAW_INT: a 3D fix where the vehicle is; during the warm-up a receiver without a fix; once
     * lost, none (AP_GPS clears its state: no position, unknown DOPs). time_usec is the time since boot.
     */
    msg_gps_raw_int gpsRaw(boolean located, Position at, long bootMillis) {
        msg_gps_raw_int g = new msg_gps_raw_int();
        g.eph = UNKNOWN_DOP;
        g.epv = UNKNOWN_DOP;
        g.fix_type = (short) (gpsLost ? GPS_FIX_TYPE.GPS_FIX_TYPE_NO_GPS : GPS_FIX_TYPE.GPS_FIX_TYPE_NO_FIX);
        if (gpsLost || !located) {
            return g;
        }
        g.fix_type = GPS_FIX_TYPE.GPS_FIX_TYPE_3D_FIX;
        g.lat = MissionItem.degE7(at.latitudeDegrees());
        g.lon = MissionItem.degE7(at.longitudeDegrees());
        g.alt = (int) Math.round(at.hae() * 1000);
        g.eph = HDOP;
        g.epv = VDOP;
        g.satellites_visible = SATELLITES;
        g.time_usec = bootMillis * 1000;
        return g;
    }
}
