package dolphin.mission.transfer;

import dolphin.mavlink.LinkTimeouts;
import java.util.Objects;

/**
 * How mission transfers time their resends and which path they take (docs/decisions.md, "Transfers
 * on lossy links").
 *
 * @param timeouts the bounds of the retransmission timeout, derived from the link's measured round
 *                 trip, and how long a transfer goes on without progress before it gives up
 * @param path over MAVLink FTP, the mission item protocol, or the best the vehicle offers
 */
public record MissionTransferConfig(LinkTimeouts timeouts, TransferPath path) {

    public static final MissionTransferConfig DEFAULT = new MissionTransferConfig(LinkTimeouts.DEFAULT, TransferPath.AUTO);

    public MissionTransferConfig {
        Objects.requireNonNull(timeouts, "timeouts");
        Objects.requireNonNull(path, "path");
    }
}
