package dolphin.mavlink;

import dolphin.mavlink.codec.SigningKey;
import dolphin.mavlink.link.LinkUrl;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Set;

/**
 * How the ground station talks MAVLink (docs/mavlink.md, "The ground station"): its ids, its
 * links, signing, the telemetry rate it asks for, and an optional tlog.
 *
 * @param allowedSysids systems to listen to; empty means all
 * @param telemetryHz the rate asked for SYS_STATUS and GLOBAL_POSITION_INT (others at 1 Hz)
 */
public record MAVLinkConfig(int sysid, int compid, List<LinkUrl> links, SigningKey signingKey, Set<Integer> allowedSysids,
                            double telemetryHz, Duration heartbeatPeriod, Duration commandTimeout, int commandAttempts,
                            Path tlog) {

    public static final int DEFAULT_SYSID = 208;
    public static final int DEFAULT_COMPID = 190;
    public static final String DEFAULT_LINK = "udpin:0.0.0.0:14559";
    public static final int DEFAULT_COMMAND_ATTEMPTS = 5;

    public MAVLinkConfig {
        links = List.copyOf(links);
        allowedSysids = Set.copyOf(allowedSysids);
        if (links.isEmpty()) {
            throw new IllegalArgumentException("at least one link is needed, e.g. " + DEFAULT_LINK);
        }
        if (!(telemetryHz > 0)) {
            throw new IllegalArgumentException("the telemetry rate must be positive, got " + telemetryHz);
        }
        if (commandAttempts < 1) {
            throw new IllegalArgumentException("a command needs at least one attempt, got " + commandAttempts);
        }
    }

    public static MAVLinkConfig of(String... links) {
        return of(java.util.Arrays.stream(links).map(LinkUrl::parse).toList());
    }

    /** The defaults: sysid 208, compid 190, telemetry at 4 Hz, 1 s heartbeats, commands tried 5 times 1 s apart. */
    public static MAVLinkConfig of(List<LinkUrl> links) {
        return new MAVLinkConfig(DEFAULT_SYSID, DEFAULT_COMPID, links, null, Set.of(), 4, Duration.ofSeconds(1),
                Duration.ofMillis(1000), DEFAULT_COMMAND_ATTEMPTS, null);
    }

    public MAVLinkConfig withSysid(int id) {
        return new MAVLinkConfig(id, compid, links, signingKey, allowedSysids, telemetryHz, heartbeatPeriod, commandTimeout,
                commandAttempts, tlog);
    }

    public MAVLinkConfig withSigningKey(SigningKey key) {
        return new MAVLinkConfig(sysid, compid, links, key, allowedSysids, telemetryHz, heartbeatPeriod, commandTimeout,
                commandAttempts, tlog);
    }

    public MAVLinkConfig withTlog(Path file) {
        return new MAVLinkConfig(sysid, compid, links, signingKey, allowedSysids, telemetryHz, heartbeatPeriod, commandTimeout,
                commandAttempts, file);
    }

    /** Sends of a COMMAND_LONG before it ends unanswered: more for lossy radio links. */
    public MAVLinkConfig withCommandAttempts(int attempts) {
        return new MAVLinkConfig(sysid, compid, links, signingKey, allowedSysids, telemetryHz, heartbeatPeriod, commandTimeout,
                attempts, tlog);
    }

    public MAVLinkConfig withAllowedSysids(Set<Integer> ids) {
        return new MAVLinkConfig(sysid, compid, links, signingKey, ids, telemetryHz, heartbeatPeriod, commandTimeout,
                commandAttempts, tlog);
    }
}
