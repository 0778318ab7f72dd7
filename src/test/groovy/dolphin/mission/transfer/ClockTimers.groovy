package dolphin.mission.transfer

import dolphin.core.ManualClock
import dolphin.mavlink.ProtocolTimers
import java.time.Duration

/**
 * The protocol's thread for specs: an action runs at once, on the caller's thread; a timeout runs
 * when the manual clock is advanced past it, at its exact clock time.
 */
class ClockTimers implements ProtocolTimers {

    final ManualClock clock

    ClockTimers(ManualClock clock) {
        this.clock = clock
    }

    @Override
    void execute(Runnable action) {
        action.run()
    }

    @Override
    void schedule(Duration delay, Runnable action) {
        clock.schedule(delay, action)
    }

    @Override
    long nanoTime() {
        clock.nanoTime()
    }
}
