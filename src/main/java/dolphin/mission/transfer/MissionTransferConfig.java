package dolphin.mission.transfer;

import dolphin.mavlink.LinkTimeouts;
import java.time.Duration;

/**
 * Timeouts and retries of mission transfers (the MAVLink mission protocol's recommended 1.5 s and 5 tries, as QGroundControl uses; docs/decisions.md,
 * "Mission transfers").
 *
 * @param timeout how long, in clock time, to wait for the vehicle's next message before sending again
 * @param tries how many times a message (MISSION_COUNT, an item, MISSION_REQUEST_LIST, a request) is sent
 *              without an answer before the transfer fails
 */
public record MissionTransferConfig(Duration timeout, int tries, LinkTimeouts timeouts, TransferPath path) {

    public static final long DEFAULT_TIMEOUT_MILLIS = 1500;
    public static final int DEFAULT_TRIES = 5;
    public static final MissionTransferConfig DEFAULT =
            new MissionTransferConfig(Duration.ofMillis(DEFAULT_TIMEOUT_MILLIS), DEFAULT_TRIES);

    public MissionTransferConfig(Duration timeout, int tries) {
        this(timeout, tries, LinkTimeouts.DEFAULT, TransferPath.AUTO);
    }

    public MissionTransferConfig(LinkTimeouts timeouts, TransferPath path) {
        this(Duration.ofMillis(DEFAULT_TIMEOUT_MILLIS), DEFAULT_TRIES, timeouts, path);
    }

    public MissionTransferConfig {
        if (timeout == null || timeout.isNegative() || timeout.isZero()) {
            throw new IllegalArgumentException("the mission transfer timeout must be positive, got " + timeout);
        }
        if (tries < 1) {
            throw new IllegalArgumentException("mission transfers need at least 1 try, got " + tries);
        }
    }

    /** "1.5 s", for messages. */
    String timeoutText() {
        return java.math.BigDecimal.valueOf(timeout.toMillis(), 3).stripTrailingZeros().toPlainString() + " s";
    }
}
