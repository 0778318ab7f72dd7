package dolphin.mission.flight;

import dolphin.mission.model.FlightLimits;
import java.time.Duration;

/**
 * How a {@link MissionExecutor} flies a mission: whether to verify the upload by downloading it
 * back, and the deadlines, all in clock time.
 *
 * @param prepare how long to wait for the vehicle to become ready (a position estimate, a home,
 *        passing pre-arm checks, DO_SET_HOME accepted): ArduPilot needs about 40 s after boot
 * @param arm how long to keep trying to arm
 * @param retry the pause between attempts to arm or to set home
 * @param stallLimit how long the vehicle may make no progress toward its item, or its landing, before it is an
 *        error (a mission's {@code stallLimit} overrides it)
 * @param takeoverTimeout how long someone else may hold the vehicle out of AUTO in a takeover mode before the
 *        mission fails (a mission's {@code takeoverTimeout} overrides it)
 * @param modeGrace how long after leaving AUTO at the last item the mission's end may still be reported
 *        (ArduPlane switches to RTL just before it reports the last item reached)
 */
public record MissionExecutorConfig(boolean verify, Duration prepare, Duration upload, Duration arm, Duration retry,
                                    Duration start, Duration stallLimit, Duration takeoverTimeout, Duration modeGrace) {

    /** The longest wait before a stall's warning line. */
    private static final Duration MOST_STALL_WARNING = Duration.ofSeconds(20);

    public static final MissionExecutorConfig DEFAULT = new MissionExecutorConfig(true, Duration.ofMinutes(3),
            Duration.ofSeconds(120), Duration.ofSeconds(90), Duration.ofSeconds(2), Duration.ofSeconds(30),
            Duration.ofSeconds(60), Duration.ofSeconds(120), Duration.ofSeconds(3));

    public MissionExecutorConfig {
        for (Duration d : new Duration[] {prepare, upload, arm, retry, start, stallLimit, takeoverTimeout, modeGrace}) {
            if (d == null || d.isNegative()) {
                throw new IllegalArgumentException("mission executor deadlines must not be negative, got " + d);
            }
        }
    }

    public MissionExecutorConfig withVerify(boolean on) {
        return new MissionExecutorConfig(on, prepare, upload, arm, retry, start, stallLimit, takeoverTimeout, modeGrace);
    }

    public MissionExecutorConfig withPrepare(Duration deadline) {
        return new MissionExecutorConfig(verify, deadline, upload, arm, retry, start, stallLimit, takeoverTimeout, modeGrace);
    }

    public MissionExecutorConfig withArm(Duration deadline) {
        return new MissionExecutorConfig(verify, prepare, upload, deadline, retry, start, stallLimit, takeoverTimeout, modeGrace);
    }

    public MissionExecutorConfig withStallLimit(Duration limit) {
        return new MissionExecutorConfig(verify, prepare, upload, arm, retry, start, limit, takeoverTimeout, modeGrace);
    }

    /** How long without progress before a line says so, once per stall: a third of the stall limit, at most 20 s. */
    public Duration stallWarning() {
        Duration third = stallLimit.dividedBy(3);
        return third.compareTo(MOST_STALL_WARNING) < 0 ? third : MOST_STALL_WARNING;
    }

    /** With a mission's own stall limit and takeover timeout, where its script sets them. */
    public MissionExecutorConfig with(FlightLimits limits) {
        MissionExecutorConfig c = limits.stall().map(this::withStallLimit).orElse(this);
        return limits.takeover().map(c::withTakeoverTimeout).orElse(c);
    }

    public MissionExecutorConfig withTakeoverTimeout(Duration timeout) {
        return new MissionExecutorConfig(verify, prepare, upload, arm, retry, start, stallLimit, timeout, modeGrace);
    }
}
