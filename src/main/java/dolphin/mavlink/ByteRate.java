package dolphin.mavlink;

/**
 * Bytes per second over the last {@link #SECONDS} whole seconds of clock time, summed in one-second
 * buckets: steady enough to read, recent enough to see a link fade, and a fixed few longs however
 * fast the link. Not thread-safe: its {@link LinkTraffic} holds the lock.
 */
final class ByteRate {

    static final int SECONDS = 5;
    private static final long SECOND = 1_000_000_000L;

    /** The bucket of each of the last seconds, and of the one going on, by second modulo their count. */
    private final long[] buckets = new long[SECONDS + 1];
    private final long firstSecond;
    private long newestSecond;
    private long total;

    ByteRate(long nowNanos) {
        firstSecond = Math.floorDiv(nowNanos, SECOND);
        newestSecond = firstSecond;
    }

    void add(long nowNanos, int bytes) {
        roll(nowNanos);
        buckets[slot(newestSecond)] += bytes;
        total += bytes;
    }

    /** Every byte counted so far. */
    long total() {
        return total;
    }

    /** The mean over the whole seconds before the current one, at most {@link #SECONDS}; 0 in the first second. */
    double perSecond(long nowNanos) {
        roll(nowNanos);
        long whole = Math.min(SECONDS, newestSecond - firstSecond);
        long sum = 0;
        for (long s = newestSecond - whole; s < newestSecond; s++) {
            sum += buckets[slot(s)];
        }
        return whole == 0 ? 0 : (double) sum / whole;
    }

    /** Empties the buckets of the seconds that began since the newest one, so old bytes leave the mean. */
    private void roll(long nowNanos) {
        long now = Math.floorDiv(nowNanos, SECOND);
        for (long s = newestSecond + 1; s <= Math.min(now, newestSecond + buckets.length); s++) {
            buckets[slot(s)] = 0;
        }
        newestSecond = Math.max(newestSecond, now);
    }

    private int slot(long second) {
        return (int) Math.floorMod(second, (long) buckets.length);
    }
}
