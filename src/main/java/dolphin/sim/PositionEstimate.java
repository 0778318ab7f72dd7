package dolphin.sim;

import java.util.Optional;

/**
 * ArduPilot's EKF at boot: for the warm-up it has no position estimate. Meanwhile the vehicle
 * reports lat = lon = alt = 0, knows no home, refuses DO_SET_HOME and fails its pre-arm checks
 * with "PreArm: Need Position Estimate", which it repeats while disarmed every 30 s, the first
 * time 15 s after boot (AP_Arming_Copter::update counts from half the period).
 */
final class PositionEstimate {

    static final String FAILURE = "PreArm: Need Position Estimate";
    static final long REPORT_PERIOD = 30_000_000_000L;

    private final long ready;
    private long nextReport;

    PositionEstimate(long bootNanos, double warmupSeconds) {
        this.ready = bootNanos + (long) (warmupSeconds * 1e9);
        this.nextReport = bootNanos + REPORT_PERIOD / 2;
    }

    boolean ready(long now) {
        return now >= ready;
    }

    /** The failure to report again at {@code now}, if it is time to. */
    Optional<String> periodicReport(long now, boolean armed) {
        if (now < nextReport) {
            return Optional.empty();
        }
        while (nextReport <= now) {
            nextReport += REPORT_PERIOD;
        }
        return armed || ready(now) ? Optional.empty() : Optional.of(FAILURE);
    }
}
