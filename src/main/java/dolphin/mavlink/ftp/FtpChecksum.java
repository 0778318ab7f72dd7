package dolphin.mavlink.ftp;

import java.util.concurrent.CompletableFuture;

/**
 * Asks the vehicle for the CRC32 of a whole file (CalcFileCRC32): one request and a 4-byte answer,
 * the vehicle reading the file itself. Nothing is opened, so nothing is closed: the session just
 * ends.
 */
final class FtpChecksum implements FtpSession.Owner {

    private final FtpSession session;
    private final CompletableFuture<Long> result = new CompletableFuture<>();

    FtpChecksum(FtpSession session) {
        this.session = session;
        session.serve(this);
    }

    CompletableFuture<Long> start() {
        session.sendPath(FtpPayload.CALC_FILE_CRC32);
        return result;
    }

    /** Stops asking: the answer is no longer wanted. */
    void cancel() {
        session.finish();
    }

    @Override
    public void answered(FtpPayload request, FtpPayload reply) {
        session.finish();
        byte[] d = reply.data();
        if (reply.opcode() == FtpPayload.ACK && d.length >= 4) {
            result.complete((d[0] & 0xffL) | (d[1] & 0xffL) << 8 | (d[2] & 0xffL) << 16 | (d[3] & 0xffL) << 24);
        } else {
            result.completeExceptionally(FtpException.refused(session.path(), request, reply));
        }
    }

    @Override
    public void unmatched(FtpPayload reply) {
        // a duplicate of the answer: already taken
    }

    @Override
    public void failed(FtpException e) {
        result.completeExceptionally(e);
    }
}
