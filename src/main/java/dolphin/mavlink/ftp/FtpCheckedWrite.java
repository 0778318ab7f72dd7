package dolphin.mavlink.ftp;

import java.util.OptionalLong;
import java.util.concurrent.CompletableFuture;
import java.util.function.Supplier;

/**
 * Writes a whole file and asks for the vehicle's CRC32 of it (CalcFileCRC32) right behind the
 * TerminateSession that closes it, so the check costs no round trip of its own. ArduPilot's FTP
 * thread serves requests in the order they come and its replies leave in that order: a CRC that
 * comes after the TerminateSession's ACK was computed on the closed file. One that comes before
 * it (the TerminateSession lost on the way, or its ACK) may be that of the file before, and is
 * asked for again once the file is closed.
 */
final class FtpCheckedWrite {

    private final FtpWrite write;
    private final Supplier<FtpSession> checksumSession;
    private final CompletableFuture<CheckedFile> result = new CompletableFuture<>();
    private FtpChecksum checksum;
    private boolean checksumEarly;  // the CRC's answer came before the file was known closed
    private FtpFile written;

    /** @param checksumSession opens a new session of the file for each CRC asked */
    FtpCheckedWrite(FtpSession session, byte[] bytes, FtpProgress progress, Supplier<FtpSession> checksumSession) {
        this.write = new FtpWrite(session, bytes, progress, this::askChecksum);
        this.checksumSession = checksumSession;
    }

    CompletableFuture<CheckedFile> start() {
        write.start().whenComplete((file, e) -> {
            if (e != null) {
                if (checksum != null) {
                    checksum.cancel();
                }
                result.completeExceptionally(e);
            } else {
                written = file;
                if (checksumEarly) {
                    askChecksum();
                }
            }
        });
        return result;
    }

    private void askChecksum() {
        checksumEarly = false;
        FtpChecksum asked = new FtpChecksum(checksumSession.get());
        checksum = asked;
        asked.start().whenComplete((crc, e) -> {
            if (written == null) {
                checksumEarly = true;
            } else if (checksum == asked) {
                result.complete(new CheckedFile(written, e == null ? OptionalLong.of(crc) : OptionalLong.empty()));
            }
        });
    }
}
