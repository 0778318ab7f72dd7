package dolphin.mavlink.ftp;

import com.MAVLink.Messages.MAVLinkMessage;
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
}
