package dolphin.mavlink;

/**
 * The measured round trip of one vehicle's link, as TCP measures it (RFC 6298): a smoothed round
 * trip and its mean deviation, fed with unambiguous samples only (an answer to a message sent
 * once: Karn's rule, the caller's duty) from command ACKs, mission transfers and MAVLink FTP.
 * Thread-safe.
 */
public final class RoundTrip {

    private static final long CLOCK_GRANULARITY_NANOS = 1_000_000;

    private long smoothed = -1;
    private long deviation;
    private long samples;

    /** A round trip measured in clock time, in nanoseconds; ignored when negative. */
    public synchronized void sample(long nanos) {
        if (nanos < 0) {
            return;
        }
        if (samples == 0) {
            smoothed = nanos;
            deviation = nanos / 2;
        } else {
            deviation = (3 * deviation + Math.abs(smoothed - nanos)) / 4;
            smoothed = (7 * smoothed + nanos) / 8;
        }
        samples++;
    }

    /**
     * The retransmission timeout, smoothed round trip plus four deviations, in nanoseconds; before
     * any sample, {@code initial}.
     */
    public synchronized long timeoutNanos(long initial) {
        return samples == 0 ? initial : smoothed + Math.max(CLOCK_GRANULARITY_NANOS, 4 * deviation);
    }

    /** The smoothed round trip in nanoseconds, or -1 before any sample. */
    public synchronized long smoothedNanos() {
        return smoothed;
    }

    /** The mean deviation in nanoseconds (0 before any sample). */
    public synchronized long deviationNanos() {
        return deviation;
    }

    public synchronized long samples() {
        return samples;
    }

    @Override
    public synchronized String toString() {
        return samples == 0 ? "no round trip measured"
                : String.format(java.util.Locale.ROOT, "round trip %.1f ms ± %.1f ms (%d samples)", smoothed / 1e6,
                        deviation / 1e6, samples);
    }
}
