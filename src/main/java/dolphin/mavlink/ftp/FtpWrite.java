package dolphin.mavlink.ftp;

import java.util.Arrays;
import java.util.BitSet;
import java.util.concurrent.CompletableFuture;

/**
 * Writes a whole file over one session: CreateFile, WriteFile of up to 239 bytes (fewer on a radio,
 * {@link FtpChannel#pacing}) with at most
 * the session's window outstanding (each sent again on its own timeout), then TerminateSession,
 * whose answer is the vehicle's verdict on the file (ArduPilot parses an @MISSION file when it is
 * closed).
 */
final class FtpWrite implements FtpSession.Owner {

    private final FtpSession session;
    private final byte[] bytes;
    private final FtpProgress progress;
    private final CompletableFuture<FtpFile> result = new CompletableFuture<>();
    private final BitSet acked = new BitSet();
    private final int block;        // file bytes per WriteFile
    private final int blocks;
    private int next = -1;          // the next block to send; -1 until the file is open
    private long done;
    private boolean reset;
    private boolean closing;

    FtpWrite(FtpSession session, byte[] bytes, FtpProgress progress) {
        this.session = session;
        this.bytes = bytes.clone();
        this.progress = progress;
        this.block = session.dataBytes();
        this.blocks = (bytes.length + block - 1) / block;
        session.serve(this);
    }

    CompletableFuture<FtpFile> start() {
        session.sendPath(FtpPayload.CREATE_FILE);
        return result;
    }

    @Override
    public void answered(FtpPayload request, FtpPayload reply) {
        boolean ack = reply.opcode() == FtpPayload.ACK;
        switch (request.opcode()) {
            case FtpPayload.CREATE_FILE -> {
                if (ack) {
                    next = 0;
                } else if (!reset && FtpErrors.busy(reply)) {
                    // sessions of ours left open (their TerminateSession lost): close them all, then create again
                    reset = true;
                    session.send(FtpPayload.RESET_SESSIONS, 0, 0, null);
                    return;
                } else {
                    session.fail(FtpException.refused(session.path(), request, reply));
                    return;
                }
            }
            case FtpPayload.RESET_SESSIONS -> {
                session.sendPath(FtpPayload.CREATE_FILE);
                return;
            }
            case FtpPayload.WRITE_FILE -> {
                if (!ack) {
                    session.fail(FtpException.refused(session.path(), request, reply));
                    return;
                }
                int b = (int) (request.offset() / block);
                if (!acked.get(b)) {
                    acked.set(b);
                    done += request.size();
                    progress.progress(done, bytes.length, session.resends());
                }
            }
            case FtpPayload.TERMINATE_SESSION -> {
                // the file is closed either way: nothing more to close
                session.finish();
                if (ack) {
                    result.complete(new FtpFile(session.path(), bytes.clone(), session.resends()));
                } else {
                    result.completeExceptionally(FtpException.refused(session.path(), request, reply));
                }
                return;
            }
            default -> {
                return;
            }
        }
        advance();
    }

    private void advance() {
        while (next < blocks && session.free() > 0) {
            int from = next * block;
            byte[] chunk = Arrays.copyOfRange(bytes, from, Math.min(bytes.length, from + block));
            session.send(FtpPayload.WRITE_FILE, chunk.length, from, chunk);
            next++;
        }
        if (!closing && acked.cardinality() == blocks) {
            closing = true;
            session.send(FtpPayload.TERMINATE_SESSION, 0, 0, null);
        }
    }

    @Override
    public void unmatched(FtpPayload reply) {
        // a duplicate or a late reply: already counted
    }

    @Override
    public void failed(FtpException e) {
        result.completeExceptionally(e);
    }
}
