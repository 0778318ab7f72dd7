package dolphin.mavlink;

import java.time.Duration;

/**
 * The bounds of a protocol's retransmission timeout and its patience (docs/decisions.md,
 * "Transfers on lossy links"): the timeout is derived from the link's measured round trip
 * ({@link RoundTrip}) and backed off on repeated loss, but never shorter than {@code min} nor
 * longer than {@code max}; a transfer gives up after {@code giveUp} of clock time without progress.
 */
public record LinkTimeouts(Duration min, Duration max, Duration giveUp) {

    /** 50 ms to 1.5 s, giving up after 10 s without progress (ArduPilot's own upload timeout is 8 s). */
    public static final LinkTimeouts DEFAULT = new LinkTimeouts(Duration.ofMillis(50), Duration.ofMillis(1500),
            Duration.ofSeconds(10));

    public LinkTimeouts {
        if (min == null || min.isNegative() || min.isZero()) {
            throw new IllegalArgumentException("the shortest retransmission timeout must be positive, got " + min);
        }
        if (max == null || max.compareTo(min) < 0) {
            throw new IllegalArgumentException("the longest retransmission timeout (" + max
                    + ") must be at least the shortest (" + min + ")");
        }
        if (giveUp == null || giveUp.compareTo(max) < 0) {
            throw new IllegalArgumentException("the time without progress before giving up (" + giveUp
                    + ") must be at least the longest retransmission timeout (" + max + ")");
        }
    }

    /**
     * The timeout to wait after a send, given the link's round trip and the sends lost in a row: the
     * link's, at least {@code min}, doubled per back-off (so a fast link's backs off from {@code min},
     * as TCP's from its floor), at most {@code max}.
     */
    public Duration timeout(RoundTrip link, int backoffs) {
        long nanos = Math.max(min.toNanos(), link.timeoutNanos(max.toNanos()));
        for (int i = 0; i < backoffs && nanos < max.toNanos(); i++) {
            nanos *= 2;
        }
        return Duration.ofNanos(Math.min(max.toNanos(), nanos));
    }
}
