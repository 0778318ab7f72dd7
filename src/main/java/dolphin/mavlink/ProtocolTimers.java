package dolphin.mavlink;

import java.time.Duration;

/**
 * The thread a request-and-answer protocol runs on (mission transfers, MAVLink FTP): every step and
 * timeout runs there, one at a time, on clock time. Production code passes the MAVLink
 * communications thread; protocol specs run each action at once and timeouts when a manual clock
 * is advanced.
 */
public interface ProtocolTimers {

    /** Runs the action on the protocol's thread. */
    void execute(Runnable action);

    /** Runs the action on the protocol's thread after {@code delay} of clock time. */
    void schedule(Duration delay, Runnable action);

    /** The clock's time in nanoseconds, for round trips. */
    long nanoTime();
}
