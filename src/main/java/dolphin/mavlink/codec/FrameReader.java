package dolphin.mavlink.codec;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Reads MAVLink 1 and 2 frames from a byte stream, in any chunking. After a bad frame it
 * resynchronises on the next start byte, so frames spliced into garbage are all recovered. It
 * never throws on input; every frame it drops is counted by reason in {@link #drops()}.
 *
 * <p>With a signing key, only frames signed with that key and with a timestamp newer than the
 * last of their stream (link id, system, component) pass. One reader per stream of bytes; not
 * thread-safe.
 */
public final class FrameReader {

    private static final int STX1 = 0xFE;
    private static final int STX2 = 0xFD;

    private final MessageTable table = MessageTable.get();
    private final DropCounters drops;
    private final SigningKey key;
    private final Map<Long, Long> lastTimestamp = new HashMap<>();
    private static final int VERIFIED = 1;
    private static final int UNVERIFIED = 0;
    private static final int NOT_A_FRAME = -1;
    private static final int NEED_MORE = -2;

    private byte[] buf = new byte[4096];
    private boolean atPacketEnd;
    private int start;
    private int end;

    public FrameReader() {
        this(null, new DropCounters());
    }

    public FrameReader(SigningKey key, DropCounters drops) {
        this.key = key;
        this.drops = drops;
    }

    public DropCounters drops() {
        return drops;
    }

    /** Adds bytes and hands every complete frame to {@code sink}; an incomplete tail waits for more. */
    public void feed(byte[] data, int off, int len, Consumer<Frame> sink) {
        append(data, off, len);
        parse(sink);
    }

    /**
     * Ends a datagram: frames do not span datagrams, so a frame of unknown id that ends exactly
     * here is accepted, and any incomplete tail is dropped as garbage.
     */
    public void endOfPacket(Consumer<Frame> sink) {
        atPacketEnd = true;
        try {
            parse(sink);
        } finally {
            atPacketEnd = false;
        }
        if (end > start) {
            drops.add(DropCounters.Reason.GARBAGE_BYTES, end - start);
        }
        start = 0;
        end = 0;
    }

    private void append(byte[] data, int off, int len) {
        if (end + len > buf.length) {
            System.arraycopy(buf, start, buf, 0, end - start);
            end -= start;
            start = 0;
            if (end + len > buf.length) {
                buf = Arrays.copyOf(buf, Math.max(buf.length * 2, end + len));
            }
        }
        System.arraycopy(data, off, buf, end, len);
        end += len;
    }

    private void parse(Consumer<Frame> sink) {
        while (true) {
            int p = start;
            while (p < end && (buf[p] & 0xFF) != STX2 && (buf[p] & 0xFF) != STX1) {
                p++;
            }
            if (p > start) {
                drops.add(DropCounters.Reason.GARBAGE_BYTES, p - start);
                start = p;
            }
            if (p >= end) {
                start = end = 0;
                return;
            }
            int consumed = (buf[p] & 0xFF) == STX2 ? tryV2(p, sink) : tryV1(p, sink);
            if (consumed == 0) {
                return;
            }
            start = p + consumed;
        }
    }

    /** Returns the bytes to consume at p: the frame's length, 1 to resync past a false start, 0 to wait. */
    private int tryV2(int p, Consumer<Frame> sink) {
        if (end - p < 10) {
            return incomplete();
        }
        int len = buf[p + 1] & 0xFF;
        int incompat = buf[p + 2] & 0xFF;
        boolean signed = (incompat & Frame.INCOMPAT_SIGNED) != 0;
        int frameLen = 10 + len + 2 + (signed ? 13 : 0);
        if (end - p < frameLen) {
            return incomplete();
        }
        int msgid = msgidAt(p);
        int check = checkCrc(p, 10, len, msgid, frameLen);
        if (check < UNVERIFIED) {
            return check == NEED_MORE ? 0 : 1;
        }
        if ((incompat & ~Frame.INCOMPAT_SIGNED) != 0) {
            drops.add(DropCounters.Reason.UNKNOWN_INCOMPAT_FLAGS, 1);
            return frameLen;
        }
        byte[] signature = signed ? Arrays.copyOfRange(buf, p + 10 + len + 2, p + frameLen) : null;
        if (key != null && !signatureAccepted(p, frameLen, signature)) {
            return frameLen;
        }
        sink.accept(new Frame(2, incompat, buf[p + 3] & 0xFF, buf[p + 4] & 0xFF, buf[p + 5] & 0xFF, buf[p + 6] & 0xFF,
                msgid, Arrays.copyOfRange(buf, p + 10, p + 10 + len), signature, check == VERIFIED, Arrays.copyOfRange(buf, p, p + frameLen)));
        return frameLen;
    }

    private int tryV1(int p, Consumer<Frame> sink) {
        if (end - p < 6) {
            return incomplete();
        }
        int len = buf[p + 1] & 0xFF;
        int frameLen = 6 + len + 2;
        if (end - p < frameLen) {
            return incomplete();
        }
        int msgid = msgidAt(p);
        int check = checkCrc(p, 6, len, msgid, frameLen);
        if (check < UNVERIFIED) {
            return check == NEED_MORE ? 0 : 1;
        }
        if (key != null) {
            drops.add(DropCounters.Reason.UNSIGNED, 1);
            return frameLen;
        }
        sink.accept(new Frame(1, 0, 0, buf[p + 2] & 0xFF, buf[p + 3] & 0xFF, buf[p + 4] & 0xFF, msgid,
                Arrays.copyOfRange(buf, p + 6, p + 6 + len), null, check == VERIFIED, Arrays.copyOfRange(buf, p, p + frameLen)));
        return frameLen;
    }

    /**
     * A candidate frame runs past the data: on a stream, wait for more; at the end of a datagram it
     * is a false start, so skip its start byte and look for frames inside it.
     */
    private int incomplete() {
        if (!atPacketEnd) {
            return 0;
        }
        drops.add(DropCounters.Reason.GARBAGE_BYTES, 1);
        return 1;
    }

    /**
     * VERIFIED when the checksum matches; for an unknown message id, whose checksum cannot be
     * checked, UNVERIFIED when it still looks like a whole frame (a start byte follows, or the
     * datagram ends there) and NEED_MORE when the next byte has not arrived; else NOT_A_FRAME.
     */
    private int checkCrc(int p, int header, int len, int msgid, int frameLen) {
        int extra = table.crcExtra(msgid);
        if (extra < 0) {
            int next = p + frameLen;
            int inside = knownFrameInside(p + 1, next);
            if (inside == VERIFIED) {
                drops.add(DropCounters.Reason.UNVERIFIABLE, 1);
                return NOT_A_FRAME;
            }
            if (inside == NEED_MORE) {
                return NEED_MORE;
            }
            if (next == end) {
                return atPacketEnd ? UNVERIFIED : NEED_MORE;
            }
            if ((buf[next] & 0xFF) == STX2 || (buf[next] & 0xFF) == STX1) {
                return UNVERIFIED;
            }
            drops.add(DropCounters.Reason.UNVERIFIABLE, 1);
            return NOT_A_FRAME;
        }
        if (!crcMatches(p, header, len, extra)) {
            drops.add(DropCounters.Reason.BAD_CRC, 1);
            return NOT_A_FRAME;
        }
        return VERIFIED;
    }

    /** The message id of the frame whose start byte is at q (its header must be in the buffer). */
    private int msgidAt(int q) {
        return (buf[q] & 0xFF) == STX2 ? (buf[q + 7] & 0xFF) | (buf[q + 8] & 0xFF) << 8 | (buf[q + 9] & 0xFF) << 16 : buf[q + 5] & 0xFF;
    }

    private boolean crcMatches(int q, int header, int len, int extra) {
        int crc = X25.accumulate(X25.accumulate(X25.SEED, buf, q + 1, header - 1 + len), extra);
        int at = q + header + len;
        return crc == ((buf[at] & 0xFF) | (buf[at + 1] & 0xFF) << 8);
    }

    /**
     * VERIFIED if a complete frame of a known id with a matching checksum starts in [from, to);
     * NEED_MORE if, on a stream, a start byte there begins a frame that has not fully arrived (it may
     * be a real frame that the unverifiable one around it would swallow); else NOT_A_FRAME.
     */
    private int knownFrameInside(int from, int to) {
        boolean undecided = false;
        for (int q = from; q < to; q++) {
            int stx = buf[q] & 0xFF;
            if (stx != STX2 && stx != STX1) {
                continue;
            }
            int header = stx == STX2 ? 10 : 6;
            if (end - q < header) {
                undecided = true;
                continue;
            }
            int len = buf[q + 1] & 0xFF;
            int frameLen = header + len + 2 + (stx == STX2 && (buf[q + 2] & Frame.INCOMPAT_SIGNED) != 0 ? 13 : 0);
            if (end - q < frameLen) {
                undecided = true;
                continue;
            }
            int extra = table.crcExtra(msgidAt(q));
            if (extra >= 0 && crcMatches(q, header, len, extra)) {
                return VERIFIED;
            }
        }
        return undecided && !atPacketEnd ? NEED_MORE : NOT_A_FRAME;
    }

    private boolean signatureAccepted(int p, int frameLen, byte[] signature) {
        if (signature == null) {
            drops.add(DropCounters.Reason.UNSIGNED, 1);
            return false;
        }
        if (!key.verify(buf, p, frameLen)) {
            drops.add(DropCounters.Reason.BAD_SIGNATURE, 1);
            return false;
        }
        long timestamp = 0;
        for (int i = 6; i >= 1; i--) {
            timestamp = (timestamp << 8) | (signature[i] & 0xFF);
        }
        long stream = (long) (signature[0] & 0xFF) << 16 | (buf[p + 5] & 0xFF) << 8 | (buf[p + 6] & 0xFF);
        Long last = lastTimestamp.get(stream);
        if (last != null && timestamp <= last) {
            drops.add(DropCounters.Reason.REPLAYED, 1);
            return false;
        }
        lastTimestamp.put(stream, timestamp);
        return true;
    }
}
