package dolphin.mission.transfer

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.common.msg_mission_request_int
import com.MAVLink.common.msg_mission_request_list
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.core.ManualClock
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import java.time.Duration

import static dolphin.mission.transfer.ScriptedMissionVehicle.ack
import static dolphin.mission.transfer.ScriptedMissionVehicle.count
import static dolphin.mission.transfer.ScriptedMissionVehicle.itemInt
import static dolphin.mission.transfer.ScriptedMissionVehicle.request

/**
 * A vehicle that keeps its mission as ArduPilot does (MissionItemProtocol.cpp, docs/mavlink.md),
 * behind a link that loses messages both ways at random (seeded) and delays each by a latency plus
 * a random jitter, on a manual clock. Upload: MISSION_COUNT starts it (the list is cleared) and
 * asks for item 0; an item whose seq is the one expected is taken and the next one asked for, any
 * other seq gets INVALID_SEQUENCE, the last item ACCEPTED; the request goes again after 1 s without
 * an item, and after 8 s without one the vehicle cancels (OPERATION_CANCELLED). An item when no
 * upload is in progress gets MAV_MISSION_ERROR. Download: REQUEST_LIST and MISSION_REQUEST_INT are
 * DENIED during an upload, else answered with the COUNT and the item.
 */
class LossyMissionVehicle {

    /** ArduPilot's re-request period and upload timeout. */
    static final Duration REREQUEST = Duration.ofSeconds(1)
    static final Duration UPLOAD_TIMEOUT = Duration.ofSeconds(8)
    /** How often ArduPilot's update runs (its GCS loop). */
    static final Duration TICK = Duration.ofMillis(20)

    final ManualClock clock
    final RecordingChannel channel
    final Random random
    final double loss
    final Duration latency
    final Duration jitter
    final Map<MissionType, List<MissionItem>> lists = [(MissionType.MISSION): [], (MissionType.FENCE): [], (MissionType.RALLY): []]
    /** Messages lost each way, and the uploads the vehicle cancelled. */
    int lostUp
    int lostDown
    int cancelled
    private MissionType uploading
    private MissionItem[] incoming
    private int requestI
    private long lastReceive
    private long lastRequest

    LossyMissionVehicle(ManualClock clock, RecordingChannel channel, double loss, long seed, Duration latency = Duration.ofMillis(50),
                        Duration jitter = Duration.ofMillis(20)) {
        this.clock = clock
        this.channel = channel
        this.loss = loss
        this.random = new Random(seed)
        this.latency = latency
        this.jitter = jitter
        channel.receiver = { MAVLinkMessage m -> fromGround(m) }
    }

    List<MissionItem> getStored() { lists[MissionType.MISSION] }

    private Duration delay() {
        latency + Duration.ofNanos((long) (random.nextDouble() * jitter.toNanos()))
    }

    private void fromGround(MAVLinkMessage m) {
        if (random.nextDouble() < loss) {
            lostUp++
            channel.markLost()
            return
        }
        clock.schedule(delay()) { receive(m) }
    }

    private void reply(MAVLinkMessage m) {
        if (random.nextDouble() < loss) {
            lostDown++
            return
        }
        clock.schedule(delay()) { channel.receive(m) }
    }

    private void receive(MAVLinkMessage m) {
        switch (m) {
            case msg_mission_count: onCount(m as msg_mission_count); break
            case msg_mission_item_int: onItem(m as msg_mission_item_int); break
            case msg_mission_request_list: onList(MissionType.of((m as msg_mission_request_list).mission_type)); break
            case msg_mission_request_int: onRequest(m as msg_mission_request_int); break
            default: break      // the download's final ACK
        }
    }

    private void onCount(msg_mission_count m) {
        MissionType type = MissionType.of(m.mission_type)
        lists[type] = []
        if (m.count == 0) {
            uploading = null
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED, type))
            return
        }
        boolean ticking = uploading != null
        uploading = type
        incoming = new MissionItem[m.count]
        requestI = 0
        lastReceive = clock.nanoTime()
        ask()
        if (!ticking) {
            clock.schedule(TICK) { update() }
        }
    }

    private void ask() {
        lastRequest = clock.nanoTime()
        reply(request(requestI, uploading))
    }

    /** ArduPilot's MissionItemProtocol::update: the re-request, and the upload timeout. */
    private void update() {
        if (uploading == null) {
            return
        }
        long now = clock.nanoTime()
        if (now - lastReceive > UPLOAD_TIMEOUT.toNanos()) {
            cancelled++
            MissionType type = uploading
            uploading = null
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED, type))
            return
        }
        if (now - lastRequest > REREQUEST.toNanos()) {
            ask()
        }
        clock.schedule(TICK) { update() }
    }

    private void onItem(msg_mission_item_int m) {
        MissionType type = MissionType.of(m.mission_type)
        if (uploading != type) {
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR, type))
            return
        }
        if (m.seq != requestI) {
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE, type))
            return
        }
        incoming[requestI++] = MissionItem.fromMessage(m)
        lastReceive = clock.nanoTime()
        if (requestI < incoming.length) {
            ask()
        } else {
            lists[type] = incoming as List
            uploading = null
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED, type))
        }
    }

    private void onList(MissionType type) {
        reply(uploading != null ? ack(MAV_MISSION_RESULT.MAV_MISSION_DENIED, type) : count(lists[type].size(), type))
    }

    private void onRequest(msg_mission_request_int m) {
        MissionType type = MissionType.of(m.mission_type)
        if (uploading != null) {
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_DENIED, type))
        } else if (m.seq >= lists[type].size()) {
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE, type))
        } else {
            reply(itemInt(lists[type][m.seq], type))
        }
    }
}
