package dolphin.mission.transfer;

import java.time.Duration;

/**
 * The thread the transfer protocols run on: every step and timeout runs there, one at a time.
 * Production code passes the MAVLink communications thread; protocol specs run each action at once
 * and timeouts when a manual clock is advanced.
 */
public interface ProtocolTimers {

    /** Runs the action on the protocol's thread. */
    void execute(Runnable action);

    /** Runs the action on the protocol's thread after {@code delay} of clock time. */
    void schedule(Duration delay, Runnable action);
}
