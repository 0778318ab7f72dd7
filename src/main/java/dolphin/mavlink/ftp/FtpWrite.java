package dolphin.mavlink.ftp;

import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;

/**
 * Writes a whole file over one session: CreateFile, WriteFile of up to 239 bytes (fewer on a radio,
 * {@link FtpChannel#pacing}, as soon as one is heard) with at most the session's window outstanding
 * (each sent again on its own timeout), then TerminateSession, whose answer is the vehicle's verdict
 * on the file (ArduPilot parses an @MISSION file when it is closed).
 *
 * <p>The first writes follow the CreateFile without waiting for its answer, as MAVProxy's do: on a
 * radio that wait is a round trip of time slots. ArduPilot's FTP thread serves requests in the
 * order they come, so a write that arrives after the CreateFile finds the file open; one refused
 * before the file is known to be open (the CreateFile lost on the way) is written again once it
 * is, and its FileNotFound sends the CreateFile again at once. A write's ACK proves the file open:
 * the CreateFile is no longer waited for, since asked again after other replies ArduPilot would
 * refuse it (the session has a file open).
 */
final class FtpWrite implements FtpSession.Owner {

    /** Where the write stands; writes may be outstanding in CREATING and WRITING. */
    private enum WritePhase { CREATING, RESETTING, WRITING, CLOSING }

    private final FtpSession session;
    private final byte[] bytes;
    private final FtpProgress progress;
    private final Runnable closing;
    private final CompletableFuture<FtpFile> result = new CompletableFuture<>();
    private final Set<Long> acked = new HashSet<>();                       // offsets written
    private final SortedMap<Long, Integer> refusedEarly = new TreeMap<>();  // offset, size: refused before the file was known open
    private WritePhase phase = WritePhase.CREATING;
    private long nextOffset;        // the first byte never sent since the file was last created
    private long done;              // bytes written
    private boolean reset;

    /** @param closing runs once the TerminateSession that closes the written file is sent */
    FtpWrite(FtpSession session, byte[] bytes, FtpProgress progress, Runnable closing) {
        this.session = session;
        this.bytes = bytes.clone();
        this.progress = progress;
        this.closing = closing;
        session.serve(this);
    }

    CompletableFuture<FtpFile> start() {
        create();
        return result;
    }

    private void create() {
        phase = WritePhase.CREATING;
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
            phase = WritePhase.WRITING;
            advance();
        } else if (!reset && FtpErrors.busy(reply)) {
            // sessions of ours left open (their TerminateSession lost): close them all, then create
            // again and write the whole file into the new one
            reset = true;
            phase = WritePhase.RESETTING;
            session.withdraw(FtpPayload.WRITE_FILE);
            acked.clear();
            refusedEarly.clear();
            nextOffset = 0;
            done = 0;
            session.send(FtpPayload.RESET_SESSIONS, 0, 0, null);
        } else {
            session.fail(FtpException.refused(session.path(), request, reply));
        }
    }

    private void written(FtpPayload request, FtpPayload reply) {
        if (reply.opcode() != FtpPayload.ACK) {
            if (phase == WritePhase.WRITING) {
                session.fail(FtpException.refused(session.path(), request, reply));
                return;
            }
            refusedEarly.put(request.offset(), request.size());
            if (phase == WritePhase.CREATING && reply.error() == FtpErrors.FILE_NOT_FOUND) {
                // no file open when this write came: the CreateFile sent before it was lost
                session.resendLostBefore(FtpPayload.CREATE_FILE, request);
            }
            return;
        }
        if (phase == WritePhase.CREATING) {
            phase = WritePhase.WRITING;
            session.withdraw(FtpPayload.CREATE_FILE);
        }
        if (acked.add(request.offset())) {
            done += request.size();
            progress.progress(done, bytes.length, session.resends());
        }
        advance();
    }

    private void advance() {
        if (phase == WritePhase.WRITING) {
            while (!refusedEarly.isEmpty() && session.free() > 0) {
                long offset = refusedEarly.firstKey();
                send(offset, refusedEarly.remove(offset));
            }
        }
        while ((phase == WritePhase.CREATING || phase == WritePhase.WRITING) && nextOffset < bytes.length && session.free() > 0) {
            int size = (int) Math.min(session.dataBytes(), bytes.length - nextOffset);
            send(nextOffset, size);
            nextOffset += size;
        }
        if (phase == WritePhase.WRITING && done == bytes.length) {
            phase = WritePhase.CLOSING;
            session.send(FtpPayload.TERMINATE_SESSION, 0, 0, null);
            closing.run();
        }
    }

    private void send(long offset, int size) {
        session.send(FtpPayload.WRITE_FILE, size, offset, Arrays.copyOfRange(bytes, (int) offset, (int) offset + size));
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
