package dolphin.mavlink.ftp;

import java.util.Arrays;
import java.util.BitSet;
import java.util.concurrent.CompletableFuture;

/**
 * Writes a whole file over one session: CreateFile, WriteFile of up to 239 bytes (fewer on a radio,
 * {@link FtpChannel#pacing}) with at most the session's window outstanding (each sent again on its
 * own timeout), then TerminateSession, whose answer is the vehicle's verdict on the file (ArduPilot
 * parses an @MISSION file when it is closed).
 *
 * <p>The first writes follow the CreateFile without waiting for its answer, as MAVProxy's do: on a
 * radio that wait is a round trip of time slots. ArduPilot's FTP thread serves requests in the
 * order they come, so a write that arrives after the CreateFile finds the file open; one refused
 * before the file is known to be open (the CreateFile lost on the way) is written again once it
 * is. A write's ACK proves the file open: the CreateFile is no longer waited for, since asked
 * again after other replies ArduPilot would refuse it (the session has a file open).
 */
final class FtpWrite implements FtpSession.Owner {

    /** Where the write stands; writes may be outstanding in CREATING and WRITING. */
    private enum Phase { CREATING, RESETTING, WRITING, CLOSING }

    private final FtpSession session;
    private final byte[] bytes;
    private final FtpProgress progress;
    private final Runnable closing;
    private final CompletableFuture<FtpFile> result = new CompletableFuture<>();
    private final BitSet acked = new BitSet();
    private final BitSet refusedEarly = new BitSet();   // refused before the file was known open: written again
    private final int block;        // file bytes per WriteFile
    private final int blocks;
    private Phase phase = Phase.CREATING;
    private int next;               // the next block never sent since the file was last created
    private long done;
    private boolean reset;

    /** @param closing runs once the TerminateSession that closes the written file is sent */
    FtpWrite(FtpSession session, byte[] bytes, FtpProgress progress, Runnable closing) {
        this.session = session;
        this.bytes = bytes.clone();
        this.progress = progress;
        this.closing = closing;
        this.block = session.dataBytes();
        this.blocks = (bytes.length + block - 1) / block;
        session.serve(this);
    }

    CompletableFuture<FtpFile> start() {
        create();
        return result;
    }

    private void create() {
        phase = Phase.CREATING;
        session.sendPath(FtpPayload.CREATE_FILE);
        advance();
    }

    @Override
    public void answered(FtpPayload request, FtpPayload reply) {
        boolean ack = reply.opcode() == FtpPayload.ACK;
        switch (request.opcode()) {
            case FtpPayload.CREATE_FILE -> created(request, reply);
            case FtpPayload.RESET_SESSIONS -> create();
            case FtpPayload.WRITE_FILE -> written(request, reply);
            case FtpPayload.TERMINATE_SESSION -> {
                // the file is closed either way: nothing more to close
                session.finish();
                if (ack) {
                    result.complete(new FtpFile(session.path(), bytes.clone(), session.resends()));
                } else {
                    result.completeExceptionally(FtpException.refused(session.path(), request, reply));
                }
            }
            default -> {
                // no other request is sent
            }
        }
    }

    private void created(FtpPayload request, FtpPayload reply) {
        if (reply.opcode() == FtpPayload.ACK) {
            phase = Phase.WRITING;
            advance();
        } else if (!reset && FtpErrors.busy(reply)) {
            // sessions of ours left open (their TerminateSession lost): close them all, then create
            // again and write every block into the new file
            reset = true;
            phase = Phase.RESETTING;
            session.withdraw(FtpPayload.WRITE_FILE);
            acked.clear();
            refusedEarly.clear();
            next = 0;
            done = 0;
            session.send(FtpPayload.RESET_SESSIONS, 0, 0, null);
        } else {
            session.fail(FtpException.refused(session.path(), request, reply));
        }
    }

    private void written(FtpPayload request, FtpPayload reply) {
        int b = (int) (request.offset() / block);
        if (reply.opcode() != FtpPayload.ACK) {
            if (phase == Phase.WRITING) {
                session.fail(FtpException.refused(session.path(), request, reply));
            } else {
                refusedEarly.set(b);
            }
            return;
        }
        if (phase == Phase.CREATING) {
            phase = Phase.WRITING;
            session.withdraw(FtpPayload.CREATE_FILE);
        }
        if (!acked.get(b)) {
            acked.set(b);
            done += request.size();
            progress.progress(done, bytes.length, session.resends());
        }
        advance();
    }

    private void advance() {
        if (phase == Phase.WRITING) {
            for (int b = refusedEarly.nextSetBit(0); b >= 0 && session.free() > 0; b = refusedEarly.nextSetBit(b + 1)) {
                refusedEarly.clear(b);
                send(b);
            }
        }
        while ((phase == Phase.CREATING || phase == Phase.WRITING) && next < blocks && session.free() > 0) {
            send(next++);
        }
        if (phase == Phase.WRITING && acked.cardinality() == blocks) {
            phase = Phase.CLOSING;
            session.send(FtpPayload.TERMINATE_SESSION, 0, 0, null);
            closing.run();
        }
    }

    private void send(int b) {
        int from = b * block;
        byte[] chunk = Arrays.copyOfRange(bytes, from, Math.min(bytes.length, from + block));
        session.send(FtpPayload.WRITE_FILE, chunk.length, from, chunk);
    }

    @Override
    public void unmatched(FtpPayload reply) {
        // a duplicate, a late reply, or one to a request withdrawn: already dealt with
    }

    @Override
    public void failed(FtpException e) {
        result.completeExceptionally(e);
    }
}
