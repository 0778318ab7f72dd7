package dolphin.mission.transfer;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.Position;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.LinkRequests;
import dolphin.mavlink.RoundTrip;
import dolphin.mavlink.VehicleFamily;
import java.util.Optional;

/**
 * What a transfer needs of the link to its vehicle: where its messages go, the ids they carry, and
 * whether the vehicle is still heard (to say so when a transfer fails). Production code passes the
 * vehicle's MAVLink node; protocol specs pass a recording fake.
 */
public interface VehicleChannel {

    /** Sends a message to the vehicle. */
    void send(MAVLinkMessage message);

    /** The vehicle's system id, the target of every message. */
    int system();

    /** The vehicle's autopilot component id. */
    int component();

    /** Our own system id: messages targeted at another ground station are not ours. */
    int groundSystem();

    /** The vehicle's name in messages ("1", "2@2"). */
    String vehicleId();

    /** The measured round trip of the vehicle's link, which transfers feed and time their resends by. */
    RoundTrip roundTrip();

    /**
     * Whether the vehicle offers MAVLink FTP (MAV_PROTOCOL_CAPABILITY_FTP in its AUTOPILOT_VERSION),
     * empty while it has not said.
     */
    Optional<Boolean> offersFtp();

    /** Asks the vehicle again what it offers, unless it answered or an ask is on its way. */
    void askWhatItOffers();

    /** How many times the vehicle was asked what it offers without answering (0 once it answered). */
    int unansweredAsks();

    /**
     * Whether the vehicle is reached through a telemetry radio (one reports on its link, or the link
     * is a serial port): transfers then send frames the radio carries well (docs/radios.md).
     */
    boolean throughRadio();

    /** The requests in flight on the vehicle's link, which its transfers share with the other vehicles' on it. */
    LinkRequests linkRequests();

    /** The percentage free of our radio's buffer towards the vehicle (its txbuf), or -1 without a current report. */
    int radioBufferFree();

    /** The vehicle's home as it last reported it (HOME_POSITION), or null while it has not. */
    Position home();

    /** Asks the vehicle for its home now (MAV_CMD_REQUEST_MESSAGE HOME_POSITION), not waiting for its stream. */
    void askHome();

    /** The vehicle's autopilot: how it numbers a mission's items ({@link AutopilotLists}) and whether it has missions over FTP. */
    Autopilot autopilot();

    /** The vehicle's firmware family: what it keeps of an item depends on it ({@link StoredItems}). */
    VehicleFamily family();

    /** Why the vehicle is not heard ("no heartbeat within 5 s"), or empty while it is. */
    String silence();
}
