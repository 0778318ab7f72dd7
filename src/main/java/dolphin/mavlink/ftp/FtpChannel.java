package dolphin.mavlink.ftp;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.mavlink.LinkRequests;
import dolphin.mavlink.RoundTrip;

/**
 * What an {@link FtpClient} needs of the link to one vehicle: where its requests go, the ids they
 * carry, and the link's measured round trip, which its timeouts follow and its clean answers feed.
 */
public interface FtpChannel {

    /** Sends a message to the vehicle. */
    void send(MAVLinkMessage message);

    /** The vehicle's system id, the target of every request. */
    int system();

    /** The vehicle's autopilot component id. */
    int component();

    /** Our own system id: replies targeted at another ground station are not ours. */
    int groundSystem();

    /** The measured round trip of the vehicle's link. */
    RoundTrip roundTrip();

    /** How transfers load the link: a network's, or a radio's (docs/radios.md). Read when a transfer starts. */
    default FtpPacing pacing() {
        return FtpPacing.NETWORK;
    }

    /** The requests in flight on the vehicle's link, shared with the other vehicles' transfers on it; read when a transfer starts. */
    default LinkRequests linkRequests() {
        return new LinkRequests();
    }

    /**
     * How much of our telemetry radio's buffer towards the vehicle is free, in percent, from its
     * latest RADIO_STATUS (txbuf); -1 when no radio reports on the link. A filling buffer throws
     * bytes away silently, so fewer requests go out at once while it fills.
     */
    default int radioBufferFree() {
        return -1;
    }
}
