package dolphin.core;

import java.time.Duration;

/**
 * The one source of time for the runtime and the simulator: every period, timeout and sleep goes
 * through a Clock, so tests and simulations can run faster than real time.
 */
public interface Clock {

    /** Monotonic time in nanoseconds, from an arbitrary origin. */
    long nanoTime();

    /** Monotonic time in seconds, from the same origin as {@link #nanoTime()}. */
    default double seconds() {
        return nanoTime() / 1e9;
    }

    /** Sleeps for the given clock time. */
    void sleep(Duration duration) throws InterruptedException;

    /**
     * The real time a blocking I/O wait (a socket or queue timeout) should use to cover the given
     * clock time; a faster clock waits less.
     */
    long realNanos(long clockNanos);

    /** A wait that another thread can cut short, e.g. when telemetry arrives. */
    Wakeup newWakeup();

    /** A wait on a {@link Clock} that {@link #wake()} ends early. */
    interface Wakeup {
        /**
         * Waits until {@link #wake()} is called or the clock time passes. A wake that came
         * before this call ends it at once; each wake is consumed by one await.
         */
        void await(Duration timeout) throws InterruptedException;

        void wake();
    }
}
