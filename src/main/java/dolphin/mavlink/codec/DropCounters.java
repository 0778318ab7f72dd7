package dolphin.mavlink.codec;

import java.util.EnumMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLongArray;

/** Counts what a reader threw away, by reason. Thread-safe: written by the comms thread, read by anyone. */
public final class DropCounters {

    public enum Reason {
        /** A frame whose checksum did not match. */
        BAD_CRC,
        /** A frame with an incompatibility flag we do not understand. */
        UNKNOWN_INCOMPAT_FLAGS,
        /** A signed frame whose signature does not match the key. */
        BAD_SIGNATURE,
        /** An unsigned frame on a link that requires signing. */
        UNSIGNED,
        /** A signed frame whose timestamp is not newer than the last one of its stream. */
        REPLAYED,
        /** A frame-like run of bytes with an unknown message id that is not followed by another frame. */
        UNVERIFIABLE,
        /** Bytes that were not part of any frame (counted in bytes, not frames). */
        GARBAGE_BYTES
    }

    private final AtomicLongArray counts = new AtomicLongArray(Reason.values().length);
    /** Counters that also count everything counted here (all links'), or null. */
    private final DropCounters total;

    public DropCounters() {
        this(null);
    }

    /** Counters of one stream (a link's) that also add what they count to {@code total}, the sum of all streams. */
    public DropCounters(DropCounters total) {
        this.total = total;
    }

    void add(Reason r, long n) {
        counts.addAndGet(r.ordinal(), n);
        if (total != null) {
            total.add(r, n);
        }
    }

    public long get(Reason r) {
        return counts.get(r.ordinal());
    }

    /** Frames dropped for any reason (garbage bytes excluded). */
    public long frames() {
        long sum = 0;
        for (Reason r : Reason.values()) {
            if (r != Reason.GARBAGE_BYTES) {
                sum += get(r);
            }
        }
        return sum;
    }

    public Map<Reason, Long> snapshot() {
        Map<Reason, Long> m = new EnumMap<>(Reason.class);
        for (Reason r : Reason.values()) {
            m.put(r, get(r));
        }
        return m;
    }

    @Override
    public String toString() {
        return snapshot().toString();
    }
}
