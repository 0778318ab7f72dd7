package dolphin.mavlink.ftp;

import java.util.Arrays;
import java.util.BitSet;
import java.util.concurrent.CompletableFuture;
import java.util.function.ToIntFunction;

/**
 * Reads a whole file over one session: OpenFileRO, one BurstReadFile of 239-byte packets (fewer
 * bytes on a radio, {@link FtpChannel#pacing}), then
 * ReadFile for every packet the burst lost. The file ends at a short packet, at EOF, or at the
 * length the caller learns from its first bytes (an @MISSION file reports a fake size of 1 MiB).
 */
final class FtpRead implements FtpSession.Owner {

    private final FtpSession session;
    private final int block;        // file bytes per reply
    private final ToIntFunction<byte[]> length;
    private final FtpProgress progress;
    private final CompletableFuture<FtpFile> result = new CompletableFuture<>();
    private final BitSet received = new BitSet();
    private final BitSet requested = new BitSet();
    private byte[] buffer = new byte[FtpPayload.DATA_BYTES];
    private long reported = -1;
    private long end = -1;          // the file's length, once known
    private long eofAt = -1;        // nothing at or after this offset
    private long bytes;
    private boolean reset;
    private FtpPayload burst;       // the burst request: its packets are welcome even late
    private boolean bursting;       // its packets still come
    private int burstGeneration;

    /** @param length the file's whole length from its first bytes, -1 while they do not tell; null: read to the end */
    FtpRead(FtpSession session, ToIntFunction<byte[]> length, FtpProgress progress) {
        this.session = session;
        this.block = session.dataBytes();
        this.length = length;
        this.progress = progress;
        session.serve(this);
    }

    CompletableFuture<FtpFile> start() {
        session.sendPath(FtpPayload.OPEN_FILE_RO);
        return result;
    }

    @Override
    public void answered(FtpPayload request, FtpPayload reply) {
        switch (request.opcode()) {
            case FtpPayload.OPEN_FILE_RO -> opened(request, reply);
            case FtpPayload.RESET_SESSIONS -> session.sendPath(FtpPayload.OPEN_FILE_RO);
            case FtpPayload.BURST_READ_FILE -> burstPacket(reply);
            case FtpPayload.READ_FILE -> {
                if (reply.opcode() == FtpPayload.ACK) {
                    store(reply.offset(), reply.data());
                } else if (reply.error() == FtpErrors.EOF) {
                    eofAt = eofAt < 0 ? request.offset() : Math.min(eofAt, request.offset());
                } else {
                    session.fail(FtpException.refused(session.path(), request, reply));
                }
                requested.clear(blockOf(request.offset()));
            }
            default -> { }
        }
        advance();
    }

    private void opened(FtpPayload request, FtpPayload reply) {
        if (reply.opcode() == FtpPayload.ACK) {
            byte[] d = reply.data();
            reported = d.length < 4 ? -1 : (d[0] & 0xff) | (d[1] & 0xff) << 8 | (d[2] & 0xff) << 16 | (long) (d[3] & 0xff) << 24;
            burst = session.send(FtpPayload.BURST_READ_FILE, block, 0, null);
            bursting = true;
        } else if (!reset && FtpErrors.busy(reply)) {
            // sessions of ours left open (their TerminateSession lost): close them all, then open again
            reset = true;
            session.send(FtpPayload.RESET_SESSIONS, 0, 0, null);
        } else {
            session.fail(FtpException.refused(session.path(), request, reply));
        }
    }

    @Override
    public void unmatched(FtpPayload reply) {
        int d = burst == null ? 0 : (reply.seq() - burst.seq()) & 0xffff;
        if (reply.reqOpcode() == FtpPayload.BURST_READ_FILE && d >= 1 && d <= FtpSession.BURST_REPLIES) {
            session.progressed();
            burstPacket(reply);
            advance();
        }
    }

    @Override
    public void failed(FtpException e) {
        result.completeExceptionally(e);
    }

    private void burstPacket(FtpPayload p) {
        if (p.opcode() == FtpPayload.NAK) {
            if (p.error() != FtpErrors.EOF) {
                session.fail(FtpException.refused(session.path(), burst, p));
                return;
            }
            // the packets before the EOF NAK, numbered from the burst's seq + 1, reached the end
            long packets = ((p.seq() - burst.seq()) & 0xffff) - 1;
            long at = burst.offset() + packets * block;
            eofAt = eofAt < 0 ? at : Math.min(eofAt, at);
            bursting = false;
            return;
        }
        store(p.offset(), p.data());
        if (p.burstComplete()) {
            bursting = false;
            return;
        }
        // the burst ends when its packets stop coming for twice the RTO (ArduPilot paces them on slow
        // links): the lost ones are then read one by one
        int generation = ++burstGeneration;
        session.timers().schedule(session.timeouts().timeout(session.roundTrip(), 1), () -> {
            if (bursting && generation == burstGeneration && !session.ended()) {
                bursting = false;
                advance();
            }
        });
    }

    private int blockOf(long offset) {
        return (int) (offset / block);
    }

    private void store(long offset, byte[] data) {
        if (offset % block != 0 || received.get(blockOf(offset))) {
            return;
        }
        int b = blockOf(offset);
        if (data.length < block) {
            end = end < 0 ? offset + data.length : Math.min(end, offset + data.length);
        }
        int need = (int) offset + data.length;
        if (need > buffer.length) {
            buffer = Arrays.copyOf(buffer, Math.max(need, buffer.length * 2));
        }
        System.arraycopy(data, 0, buffer, (int) offset, data.length);
        received.set(b);
        bytes += data.length;
        if (length != null && end < 0 && received.get(0)) {
            // every block so far is whole (a short one ends the file): the prefix read so far
            int whole = length.applyAsInt(Arrays.copyOf(buffer, received.nextClearBit(0) * block));
            if (whole >= 0) {
                end = whole;
            }
        }
        progress.progress(bytes, end >= 0 ? end : length == null ? reported : -1, session.resends());
    }

    /** The file's length when every byte of it is here, else -1. */
    private long complete() {
        long limit = end >= 0 ? (eofAt >= 0 ? Math.min(end, eofAt) : end) : eofAt;
        if (limit < 0) {
            return -1;
        }
        int blocks = (int) ((limit + block - 1) / block);
        return received.nextClearBit(0) >= blocks ? limit : -1;
    }

    private void advance() {
        if (session.ended()) {
            return;
        }
        long whole = complete();
        if (whole >= 0) {
            session.close();
            result.complete(new FtpFile(session.path(), Arrays.copyOf(buffer, (int) whole), session.resends()));
            return;
        }
        if (bursting || reported < 0) {
            return;
        }
        long limit = end >= 0 ? end : eofAt;
        int blocks = limit < 0 ? Integer.MAX_VALUE : (int) ((limit + block - 1) / block);
        int b = 0;
        while (session.free() > 0) {
            while (received.get(b) || requested.get(b)) {
                b++;
            }
            if (b >= blocks) {
                return;
            }
            requested.set(b);
            session.send(FtpPayload.READ_FILE, block, (long) b * block, null);
        }
    }
}
