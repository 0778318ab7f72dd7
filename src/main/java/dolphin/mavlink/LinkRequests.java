package dolphin.mavlink;

/**
 * The requests in flight on one link, counted across the transfers of every vehicle on it: two
 * vehicles behind one telemetry radio share its buffer, so their transfers share one window
 * (docs/radios.md, "Whole-list transfers"). Communications thread only.
 */
public final class LinkRequests {

    private int inFlight;

    public int inFlight() {
        return inFlight;
    }

    /** {@code n} requests more in flight (fewer when negative: answered, or given up with their transfer). */
    public void add(int n) {
        inFlight = Math.max(0, inFlight + n);
    }
}
