package dolphin.sim;

import java.util.Locale;

/** A simulated vehicle as its faults see it ({@link SimVehicle}). */
interface FaultHost {

    Firmware firmware();

    Craft craft();

    boolean armed();

    int mode();

    /** Whether its own flight moves it in its present mode (AUTO, RTL, LAND), so a hold of a fault's would fight it. */
    boolean flightMoves();

    /** A STATUSTEXT, sent at the next flush (at the latest at the end of the tick). */
    void text(int severity, String text);

    /** Sends what waits, so that what follows comes after it. */
    void flush();

    /**
     * Sets the mode as a ground station's DO_SET_MODE would, with the same checks; the heartbeat that
     * shows it goes out at once. True if the vehicle took it.
     */
    boolean setMode(int mode);

    /**
     * The flight of its present mode (LAND) holds where it is for {@code seconds} before it moves, as
     * ArduCopter's set_mode_land_with_pause; the mode's landed state (LANDING) is reported meanwhile.
     */
    void pauseFlight(double seconds);

    /** Its GPS receiver and EKF, as GPS_RAW_INT, EKF_STATUS_REPORT and the heartbeat report them. */
    NavigationState navigation();

    /** EKF3 switches its primary to {@code lane}, and AP_AHRS says that the primary changed. */
    default void laneSwitch(int lane) {
        navigation().primaryLane(lane);
        text(FaultTable.LANE_SWITCH_SEVERITY, String.format(Locale.ROOT, FaultTable.LANE_SWITCH, lane));
        text(FaultTable.PRIMARY_CHANGED_SEVERITY, String.format(Locale.ROOT, FaultTable.PRIMARY_CHANGED, lane));
    }

    /** Cut off (true) the vehicle sends and hears nothing, as its radio link lost; false: heard again. */
    void cutOff(boolean cut);

    /** Reboots its autopilot now (SimVehicle#reboot). */
    void reboot();
}
