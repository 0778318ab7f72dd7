package dolphin.mavlink.ftp;

/** The MAV_FTP_ERR values the client acts on. */
final class FtpErrors {

    static final int FAIL = 1;
    static final int FAIL_ERRNO = 2;
    static final int NO_SESSIONS_AVAILABLE = 5;
    static final int EOF = 6;
    static final int FILE_NOT_FOUND = 10;
    /** The errno of an open when the vehicle's file table is full (AP_Filesystem_Mission keeps four @MISSION files). */
    static final int ENFILE = 23;

    private FtpErrors() {
    }

    /**
     * A refused open that a ResetSessions may cure: the session still has a file open, ArduPilot has
     * no free session, or no free @MISSION file (sessions of ours left open hold them all).
     */
    static boolean busy(FtpPayload nak) {
        int error = nak.error();
        return error == FAIL || error == NO_SESSIONS_AVAILABLE || (error == FAIL_ERRNO && nak.errno() == ENFILE);
    }
}
