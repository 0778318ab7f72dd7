package dolphin.mavlink.ftp;

import java.util.Locale;

/**
 * Why a file transfer failed, in words a user can act on: the vehicle refused a request ("the
 * vehicle refused @MISSION/mission.dat when closing it: FailErrno, errno 22 (EINVAL)"), or it did
 * not answer. {@link #answered()} tells a vehicle without MAVLink FTP (never a reply) from one that
 * answered and refused or fell silent later.
 */
public final class FtpException extends RuntimeException {

    private static final String[] ERRORS = {"None", "Fail", "FailErrno", "InvalidDataSize", "InvalidSession",
        "NoSessionsAvailable", "EOF", "UnknownCommand", "FileExists", "FileProtected", "FileNotFound"};

    private final String path;
    private final int error;
    private final int errno;
    private final int requestOpcode;
    private final boolean answered;

    private FtpException(String message, String path, int error, int errno, int requestOpcode, boolean answered) {
        super(message);
        this.path = path;
        this.error = error;
        this.errno = errno;
        this.requestOpcode = requestOpcode;
        this.answered = answered;
    }

    /** The vehicle answered {@code request} with {@code nak}. */
    static FtpException refused(String path, FtpPayload request, FtpPayload nak) {
        int err = nak.error();
        String why = errorName(err) + (nak.errno() >= 0 && err == 2 ? ", " + errnoText(nak.errno()) : "");
        return new FtpException("the vehicle refused " + path + " when " + doing(request) + ": " + why, path, err,
                nak.errno(), request.opcode(), true);
    }

    /** Nothing useful came back for {@code request} within {@code giveUp}. */
    static FtpException noAnswer(String path, FtpPayload request, int sends, java.time.Duration giveUp, boolean answered) {
        String s = String.format(Locale.ROOT, "%.1f", giveUp.toMillis() / 1000.0).replaceAll("\\.0$", "");
        return new FtpException((answered ? "the vehicle stopped answering MAVLink FTP" : "no MAVLink FTP answer from the vehicle")
                + " when " + doing(request) + " (" + path + ", " + FtpPayload.opcodeName(request.opcode()) + " sent " + sends
                + (sends == 1 ? " time" : " times") + ", nothing new for " + s + " s)", path, -1, -1, request.opcode(), answered);
    }

    /** The transfer was given up before its end, for {@code why}. */
    static FtpException abandoned(String path, String why, boolean answered) {
        return new FtpException(why, path, -1, -1, -1, answered);
    }

    /** The vehicle's file was not what was expected ("read 12 bytes, expected at least 10"). */
    static FtpException bad(String path, String what) {
        return new FtpException("the vehicle's " + path + " " + what, path, -1, -1, -1, true);
    }

    /** The file the transfer was about. */
    public String path() {
        return path;
    }

    /** The NAK's MAV_FTP_ERR, -1 when the vehicle did not refuse. */
    public int error() {
        return error;
    }

    /** A FailErrno NAK's errno, -1 otherwise. */
    public int errno() {
        return errno;
    }

    /** Whether the vehicle refused when the file was being closed (TerminateSession): for a written file, its verdict. */
    public boolean refusedAtClose() {
        return error >= 0 && requestOpcode == FtpPayload.TERMINATE_SESSION;
    }

    /** Whether the vehicle answered anything over FTP during the transfer; false: it may not offer FTP at all. */
    public boolean answered() {
        return answered;
    }

    /** "FailErrno", "FileNotFound": MAV_FTP_ERR as ArduPilot names it. */
    static String errorName(int error) {
        return error >= 0 && error < ERRORS.length ? ERRORS[error] : "error " + error;
    }

    /** "errno 22 (EINVAL)". */
    static String errnoText(int errno) {
        String name = switch (errno) {
            case 1 -> "EPERM";
            case 2 -> "ENOENT";
            case 5 -> "EIO";
            case 9 -> "EBADF";
            case 12 -> "ENOMEM";
            case 13 -> "EACCES";
            case 17 -> "EEXIST";
            case 20 -> "ENOTDIR";
            case 21 -> "EISDIR";
            case 22 -> "EINVAL";
            case 23 -> "ENFILE";
            case 24 -> "EMFILE";
            case 27 -> "EFBIG";
            case 28 -> "ENOSPC";
            case 30 -> "EROFS";
            case 36 -> "ENAMETOOLONG";
            default -> null;
        };
        return "errno " + errno + (name == null ? "" : " (" + name + ")");
    }

    /** "closing it", "writing 239 bytes at offset 478". */
    private static String doing(FtpPayload request) {
        return switch (request.opcode()) {
            case FtpPayload.OPEN_FILE_RO -> "opening it for reading";
            case FtpPayload.CREATE_FILE -> "creating it";
            case FtpPayload.WRITE_FILE -> "writing " + request.size() + " bytes at offset " + request.offset();
            case FtpPayload.READ_FILE, FtpPayload.BURST_READ_FILE -> "reading at offset " + request.offset();
            case FtpPayload.TERMINATE_SESSION -> "closing it";
            case FtpPayload.RESET_SESSIONS -> "resetting our sessions";
            default -> "sending " + FtpPayload.opcodeName(request.opcode());
        };
    }
}
