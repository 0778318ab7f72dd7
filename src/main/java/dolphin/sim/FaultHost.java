package dolphin.sim;

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

    /** Its GPS receiver and EKF, as GPS_RAW_INT, EKF_STATUS_REPORT and the heartbeat report them. */
    NavigationState navigation();

    /** Cut off (true) the vehicle sends and hears nothing, as its radio link lost; false: heard again. */
    void cutOff(boolean cut);

    /** Reboots its autopilot now (SimVehicle#reboot). */
    void reboot();
}
