package dolphin.web;

import dolphin.core.Clock;
import java.time.Duration;

/**
 * The latest frame, handed from the sampler to every viewer's thread. The sampler never waits for a
 * viewer: a slow one wakes up to the newest frame and is sent what changed since the one it had.
 */
final class Broadcast {

    private final Clock clock;
    private FleetFeed.FeedFrame latest;
    private boolean ended;

    Broadcast(Clock clock, FleetFeed.FeedFrame first) {
        this.clock = clock;
        latest = first;
    }

    synchronized void publish(FleetFeed.FeedFrame frame) {
        latest = frame;
        notifyAll();
    }

    /** The run is over: viewers send what is left and end their streams. */
    synchronized void end() {
        ended = true;
        notifyAll();
    }

    synchronized FleetFeed.FeedFrame latest() {
        return latest;
    }

    synchronized boolean ended() {
        return ended;
    }

    /**
     * A frame newer than {@code number}, waiting up to {@code timeout} of the clock; the latest frame
     * (maybe not newer) when the time is up or the run ended.
     */
    synchronized FleetFeed.FeedFrame awaitAfter(long number, Duration timeout) throws InterruptedException {
        long deadline = clock.nanoTime() + timeout.toNanos();
        while (latest.number() <= number && !ended) {
            long left = deadline - clock.nanoTime();
            if (left <= 0) {
                break;
            }
            wait(Math.max(1, clock.realNanos(left) / 1_000_000));
        }
        return latest;
    }
}
