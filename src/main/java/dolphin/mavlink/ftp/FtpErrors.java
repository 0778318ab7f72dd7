package dolphin.mavlink.ftp;

/** The MAV_FTP_ERR values the client acts on. */
final class FtpErrors {

    static final int FAIL = 1;
    static final int NO_SESSIONS_AVAILABLE = 5;
    static final int EOF = 6;

    private FtpErrors() {
    }

    /** A refused open that a ResetSessions may cure: the session still has a file open, or ArduPilot has no free session. */
    static boolean busy(int error) {
        return error == FAIL || error == NO_SESSIONS_AVAILABLE;
    }
}
