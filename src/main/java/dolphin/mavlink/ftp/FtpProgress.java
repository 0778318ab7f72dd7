package dolphin.mavlink.ftp;

/** Progress of a file transfer, called on the protocol's thread. */
@FunctionalInterface
public interface FtpProgress {

    FtpProgress NONE = (done, total, resends) -> { };

    /**
     * @param done bytes written and acknowledged, or read
     * @param total the file's length, -1 while unknown
     * @param resends requests sent again so far
     */
    void progress(long done, long total, int resends);
}
