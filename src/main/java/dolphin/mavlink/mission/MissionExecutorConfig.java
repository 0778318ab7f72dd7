package dolphin.mavlink.mission;

import java.time.Duration;

/**
 * How a {@link MissionExecutor} flies a mission: whether to verify the upload by downloading it
 * back, and the deadline of each state (clock time).
 *
 * @param arm how long to keep trying to arm (ArduCopter SITL accepts about 42 s after boot)
 * @param retryArm the pause between arming attempts
 */
public record MissionExecutorConfig(boolean verify, Duration prepare, Duration upload, Duration arm, Duration retryArm,
                                    Duration start) {

    public static final MissionExecutorConfig DEFAULT = new MissionExecutorConfig(true, Duration.ofSeconds(30),
            Duration.ofSeconds(120), Duration.ofSeconds(90), Duration.ofSeconds(2), Duration.ofSeconds(30));

    public MissionExecutorConfig withVerify(boolean on) {
        return new MissionExecutorConfig(on, prepare, upload, arm, retryArm, start);
    }

    public MissionExecutorConfig withArm(Duration deadline) {
        return new MissionExecutorConfig(verify, prepare, upload, deadline, retryArm, start);
    }
}
