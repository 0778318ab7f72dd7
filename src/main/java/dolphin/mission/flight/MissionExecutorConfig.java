package dolphin.mission.flight;

import java.time.Duration;

/**
 * How a {@link MissionExecutor} flies a mission: whether to verify the upload by downloading it
 * back, and the deadlines, all in clock time.
 *
 * @param prepare how long to wait for the vehicle to become ready (a position estimate, a home,
 *        passing pre-arm checks, DO_SET_HOME accepted): ArduPilot needs about 40 s after boot
 * @param arm how long to keep trying to arm
 * @param retry the pause between attempts to arm or to set home
 * @param landingStall how long a landing may make no progress (no movement, not disarmed) before it is an error
 * @param modeGrace how long after leaving AUTO at the last item the mission's end may still be reported
 *        (ArduPlane switches to RTL just before it reports the last item reached)
 */
public record MissionExecutorConfig(boolean verify, Duration prepare, Duration upload, Duration arm, Duration retry,
                                    Duration start, Duration landingStall, Duration modeGrace) {

    public static final MissionExecutorConfig DEFAULT = new MissionExecutorConfig(true, Duration.ofMinutes(3),
            Duration.ofSeconds(120), Duration.ofSeconds(90), Duration.ofSeconds(2), Duration.ofSeconds(30),
            Duration.ofSeconds(60), Duration.ofSeconds(3));

    public MissionExecutorConfig {
        for (Duration d : new Duration[] {prepare, upload, arm, retry, start, landingStall, modeGrace}) {
            if (d == null || d.isNegative()) {
                throw new IllegalArgumentException("mission executor deadlines must not be negative, got " + d);
            }
        }
    }

    public MissionExecutorConfig withVerify(boolean on) {
        return new MissionExecutorConfig(on, prepare, upload, arm, retry, start, landingStall, modeGrace);
    }

    public MissionExecutorConfig withPrepare(Duration deadline) {
        return new MissionExecutorConfig(verify, deadline, upload, arm, retry, start, landingStall, modeGrace);
    }

    public MissionExecutorConfig withArm(Duration deadline) {
        return new MissionExecutorConfig(verify, prepare, upload, deadline, retry, start, landingStall, modeGrace);
    }

    public MissionExecutorConfig withLandingStall(Duration limit) {
        return new MissionExecutorConfig(verify, prepare, upload, arm, retry, start, limit, modeGrace);
    }
}
