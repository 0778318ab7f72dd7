package dolphin.mission.transfer

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_item
import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.common.msg_mission_request
import com.MAVLink.common.msg_mission_request_int
import com.MAVLink.common.msg_mission_request_list
import dolphin.core.ManualClock
import dolphin.mavlink.RoundTrip
import dolphin.mission.model.MissionType

/**
 * Both ends of a link to one vehicle, with no socket: the {@link VehicleChannel} the transfer
 * protocols send through, which records each message with the clock time and hands it to
 * {@link #receiver} (the vehicle side, if any), and {@link #receive}, which hands a vehicle's
 * message to the transfers. The conversation both ways is kept as lines such as
 * {@code "1.5 > COUNT 5"} (sent to the vehicle) and {@code "1.5 < REQUEST 0"} (from it).
 */
class RecordingChannel implements VehicleChannel {

    /** Our ground station's system id (MAVLinkConfig's default), and its component id. */
    static final int GROUND_SYSTEM = 208
    static final int GROUND_COMPONENT = 190

    /** One message sent to the vehicle, at a clock time in seconds. */
    static class Sent {
        final double time
        final MAVLinkMessage message

        Sent(double time, MAVLinkMessage message) {
            this.time = time
            this.message = message
        }

        String toString() { "${seconds(time)} ${describe(message)}" }
    }

    final ManualClock clock
    int system = 2
    int component = 1
    String vehicleId = '2'
    /** The link's measured round trip, which the transfers feed. */
    final RoundTrip roundTrip = new RoundTrip()
    /** What the vehicle said of MAVLink FTP (empty: nothing yet); most specs fly a vehicle without it. */
    Optional<Boolean> offersFtp = Optional.of(false)
    /** The vehicle's home as it reported it (null: not yet), and its family. */
    dolphin.core.Position home
    dolphin.mavlink.VehicleFamily family = dolphin.mavlink.VehicleFamily.COPTER
    /** The vehicle's autopilot, which numbers its missions. */
    dolphin.mavlink.Autopilot firmware = dolphin.mavlink.Autopilot.ARDUPILOT
    /** Whether the vehicle is reached through a telemetry radio. */
    boolean throughRadio
    /** Our radio's free buffer in percent, -1: no radio reports. */
    int radioBufferFree = -1
    /** Times the transfers asked the vehicle what it offers. */
    int asks
    /** The vehicle side's answer to an ask, if any: it may set {@link #offersFtp}. */
    Closure answerAsk
    /** Why the vehicle is not heard, or empty; the vehicle side may replace it. */
    Closure<String> silenceText = { '' }
    /** The vehicle side: gets every message sent; null sends them nowhere. */
    Closure receiver
    /** The transfers that hear the vehicle's messages. */
    MissionTransfers transfers
    final List<Sent> sent = []
    final List<String> conversation = []

    RecordingChannel(ManualClock clock) {
        this.clock = clock
    }

    @Override
    RoundTrip roundTrip() { roundTrip }

    @Override
    Optional<Boolean> offersFtp() { offersFtp }

    @Override
    boolean throughRadio() { throughRadio }

    @Override
    int radioBufferFree() { radioBufferFree }

    /** The requests in flight on the link, which a spec may share between channels. */
    dolphin.mavlink.LinkRequests linkRequests = new dolphin.mavlink.LinkRequests()

    @Override
    dolphin.mavlink.LinkRequests linkRequests() { linkRequests }

    @Override
    dolphin.core.Position home() { home }

    /** Times a transfer asked for the vehicle's home; the vehicle side's answer, if any. */
    int homeAsks
    Closure answerHome

    @Override
    void askHome() {
        homeAsks++
        answerHome?.call()
    }

    @Override
    dolphin.mavlink.VehicleFamily family() { family }

    @Override
    dolphin.mavlink.Autopilot autopilot() { firmware }

    @Override
    void askWhatItOffers() {
        asks++
        answerAsk?.call()
    }

    @Override
    int unansweredAsks() { offersFtp.present ? 0 : asks }

    @Override
    void send(MAVLinkMessage message) {
        sent << new Sent(clock.seconds(), message)
        conversation << "${seconds(clock.seconds())} > ${describe(message)}".toString()
        receiver?.call(message)
    }

    @Override
    int system() { system }

    @Override
    int component() { component }

    @Override
    int groundSystem() { GROUND_SYSTEM }

    @Override
    String vehicleId() { vehicleId }

    @Override
    String silence() { silenceText() }

    /** A message from the vehicle, now. */
    void receive(MAVLinkMessage message) {
        conversation << "${seconds(clock.seconds())} < ${describe(message)}".toString()
        transfers.handle(message)
    }

    /** The last message sent never reached the vehicle. */
    void markLost() {
        conversation[-1] = conversation[-1] + ' (lost)'
    }

    /** What was sent, as "time text" lines: "1.5 COUNT 5". */
    List<String> sentLines() {
        sent.collect { it.toString() }
    }

    /** The messages sent again: those whose text was sent before, with the time they were sent again. */
    List<String> repeats() {
        Set<String> seen = [] as Set
        sent.findAll { !seen.add(describe(it.message)) }.collect { it.toString() }
    }

    /** "0.0", "1.5", "1.525": to the millisecond, at least one decimal. */
    static String seconds(double t) {
        BigDecimal s = BigDecimal.valueOf(Math.round(t * 1000), 3).stripTrailingZeros()
        (s.scale() < 1 ? s.setScale(1) : s).toPlainString()
    }

    /** "COUNT 5", "REQUEST_INT 3", "ITEM 2", "ACK ACCEPTED", "REQUEST_LIST"; " (fence)" or " (rally points)" for those lists. */
    static String describe(MAVLinkMessage m) {
        switch (m) {
            case msg_mission_count: return "COUNT ${m.count}${of(m.mission_type)}${to(m.target_system)}"
            case msg_mission_request: return "REQUEST ${m.seq}${of(m.mission_type)}${to(m.target_system)}"
            case msg_mission_request_int: return "REQUEST_INT ${m.seq}${of(m.mission_type)}${to(m.target_system)}"
            case msg_mission_item_int: return "ITEM ${m.seq}${of(m.mission_type)}${to(m.target_system)}"
            case msg_mission_item: return "ITEM(float) ${m.seq}${of(m.mission_type)}${to(m.target_system)}"
            case msg_mission_ack:
                return "ACK ${MissionUploadProtocol.resultName(m.type) - 'MAV_MISSION_'}${of(m.mission_type)}${to(m.target_system)}"
            case msg_mission_request_list: return "REQUEST_LIST${of(m.mission_type)}${to(m.target_system)}"
            default: return m.class.simpleName
        }
    }

    private static String of(int missionType) {
        missionType == MissionType.MISSION.wire() ? '' : " (${MissionType.of(missionType)?.label() ?: missionType})"
    }

    /** Messages between us (208) and the vehicle (2) name no target; one for another system, or for all (0), says so. */
    private static String to(int target) {
        target in [GROUND_SYSTEM, 2] ? '' : " (to ${target})"
    }
}
