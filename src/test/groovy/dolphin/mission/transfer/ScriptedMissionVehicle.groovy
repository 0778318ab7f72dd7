package dolphin.mission.transfer

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_item
import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.common.msg_mission_request
import com.MAVLink.common.msg_mission_request_int
import com.MAVLink.common.msg_mission_request_list
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.core.ManualClock
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import java.time.Duration

/**
 * The vehicle side of the mission protocol as ArduPilot does it, on a {@link RecordingChannel}
 * and a manual clock, with no socket and no thread: MISSION_REQUEST during an upload,
 * INVALID_SEQUENCE for an item out of order, a COUNT clears the list, one list per mission type.
 * It answers each message when it gets it; its answers reach the transfers after {@link #latency}
 * of clock time (zero: at the same clock time, when the clock is advanced). An item when no upload
 * is in progress gets MAV_MISSION_ERROR, as from ArduPilot. Faults by name:
 * countLost (the first COUNT), denyCount (errorAck answers COUNT), itemLost (item faultSeq, the
 * first time), requestLost (the first request for item faultSeq), duplicateRequests,
 * reorderedRequests, errorAck (result errorAck at item faultSeq), ackLost (the final ACK, the first
 * time), noAck (no final ACK, and no answer to items after the last), silentAfterLast (the vehicle takes the last
 * item, then falls silent), outOfRange, silentAt (item faultSeq: the vehicle falls silent), requestInt, listLost (the
 * first REQUEST_LIST), denyList (errorAck answers REQUEST_LIST), dlItemLost (the first request for
 * item faultSeq), dlItemNever (every request for item faultSeq), floatItems (downloads answered
 * with the float MISSION_ITEM).
 */
class ScriptedMissionVehicle {

    final ManualClock clock
    final RecordingChannel channel
    final Map<MissionType, List<MissionItem>> lists = [(MissionType.MISSION): [], (MissionType.FENCE): [], (MissionType.RALLY): []]
    Set<String> faults = [] as Set
    int faultSeq = -1
    int errorAck = -1
    Duration latency = Duration.ZERO
    /** How long a silent vehicle goes unheard before the ground station counts it lost. */
    Duration connectionTimeout = Duration.ofSeconds(5)
    private Long silentSince
    private final Set<String> once = [] as Set
    private MissionType uploading
    private MissionItem[] incoming
    private int expected = -1

    ScriptedMissionVehicle(ManualClock clock, RecordingChannel channel) {
        this.clock = clock
        this.channel = channel
        channel.receiver = { MAVLinkMessage m -> receive(m) }
        channel.silenceText = { silence() }
    }

    /** The vehicle's mission (its first list). */
    List<MissionItem> getStored() { lists[MissionType.MISSION] }

    void setStored(List<MissionItem> items) { lists[MissionType.MISSION] = items }

    boolean isSilent() { silentSince != null }

    /** Falls silent from now on: no answers, no heartbeats. */
    void setSilent(boolean silent) {
        silentSince = silent ? clock.nanoTime() : null
    }

    /** "no heartbeat within 5 s" once the vehicle has been silent for its connection timeout. */
    String silence() {
        silentSince != null && clock.nanoTime() - silentSince >= connectionTimeout.toNanos() ?
                "no heartbeat within ${connectionTimeout.toSeconds()} s".toString() : ''
    }

    private boolean first(String what) { once.add(what) }

    /** A message from the ground station, as it arrives. */
    void receive(MAVLinkMessage m) {
        if (isSilent()) {
            return
        }
        switch (m) {
            case msg_mission_count: onCount(m as msg_mission_count); break
            case msg_mission_item_int: onItem(m as msg_mission_item_int); break
            case msg_mission_request_list: onList(m as msg_mission_request_list); break
            case msg_mission_request_int: onRequest(m as msg_mission_request_int); break
            default: break      // the download's final ACK
        }
    }

    private void onCount(msg_mission_count m) {
        MissionType type = MissionType.of(m.mission_type)
        if (faults.contains('countLost') && first('count')) {
            channel.markLost()
            return
        }
        if (faults.contains('denyCount')) {
            reply(ack(errorAck, type))
            return
        }
        uploading = type
        incoming = new MissionItem[m.count]
        lists[type] = []                                 // ArduPilot clears the list on COUNT
        expected = 0
        if (m.count == 0) {
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED, type))
        } else {
            ask(0)
        }
    }

    private void onItem(msg_mission_item_int m) {
        int seq = m.seq
        if (faults.contains('itemLost') && seq == faultSeq && first('item')) {
            channel.markLost()                           // the vehicle does not ask again: the ground station's timer must
            return
        }
        if (expected < 0 || MissionType.of(m.mission_type) != uploading) {
            if (!faults.contains('noAck')) {
                reply(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR, MissionType.of(m.mission_type)))  // no upload in progress
            }
            return
        }
        if (seq != expected) {
            reply(ack(MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE, uploading))
            return
        }
        if (faults.contains('silentAt') && seq == faultSeq) {
            setSilent(true)
            return
        }
        if (faults.contains('errorAck') && seq == faultSeq) {
            expected = -1
            reply(ack(errorAck, uploading))
            return
        }
        incoming[seq] = MissionItem.fromMessage(m)
        expected++
        if (faults.contains('outOfRange') && seq == 1) {
            ask(incoming.length + 2)
        } else if (expected == incoming.length) {
            lists[uploading] = incoming as List
            expected = -1
            if (faults.contains('silentAfterLast')) {
                setSilent(true)
            } else if (!faults.contains('noAck') && !(faults.contains('ackLost') && first('ack'))) {
                reply(ack(MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED, uploading))
            }
        } else if (faults.contains('reorderedRequests') && seq >= 1) {
            ask(expected)
            ask(seq)                                 // a stale request arriving late
        } else {
            ask(expected)
        }
    }

    private void ask(int seq) {
        if (faults.contains('requestLost') && seq == faultSeq && first('request')) {
            return
        }
        MAVLinkMessage r = faults.contains('requestInt') ? requestInt(seq, uploading) : request(seq, uploading)
        reply(r)
        if (faults.contains('duplicateRequests')) {
            reply(r)
        }
    }

    private void onList(msg_mission_request_list m) {
        MissionType type = MissionType.of(m.mission_type)
        if (faults.contains('listLost') && first('list')) {
            channel.markLost()
            return
        }
        if (faults.contains('denyList')) {
            reply(ack(errorAck, type))
            return
        }
        reply(count(lists[type].size(), type))
    }

    private void onRequest(msg_mission_request_int m) {
        MissionType type = MissionType.of(m.mission_type)
        if ((faults.contains('dlItemLost') && m.seq == faultSeq && first('dl')) || (faults.contains('dlItemNever') && m.seq == faultSeq)) {
            channel.markLost()
            return
        }
        MissionItem item = lists[type][m.seq]
        reply(faults.contains('floatItems') ? floatItem(item, type) : itemInt(item, type))
    }

    /** Sends a message to the ground station; it arrives after the latency unless the vehicle falls silent meanwhile. */
    private void reply(MAVLinkMessage m) {
        clock.schedule(latency) {
            if (!isSilent()) {
                channel.receive(m)
            }
        }
    }

    // ---- the vehicle's messages, to our ground station unless told otherwise

    static MAVLinkMessage request(int seq, MissionType type = MissionType.MISSION, int target = RecordingChannel.GROUND_SYSTEM) {
        addressed(new msg_mission_request(seq: seq), type, target)
    }

    static MAVLinkMessage requestInt(int seq, MissionType type = MissionType.MISSION, int target = RecordingChannel.GROUND_SYSTEM) {
        addressed(new msg_mission_request_int(seq: seq), type, target)
    }

    static MAVLinkMessage ack(int result, MissionType type = MissionType.MISSION, int target = RecordingChannel.GROUND_SYSTEM) {
        addressed(new msg_mission_ack(type: result as short), type, target)
    }

    static MAVLinkMessage count(int count, MissionType type = MissionType.MISSION, int target = RecordingChannel.GROUND_SYSTEM) {
        addressed(new msg_mission_count(count: count), type, target)
    }

    /** The message of the list {@code type}, to the ground station {@code target}. */
    private static MAVLinkMessage addressed(MAVLinkMessage m, MissionType type, int target) {
        m.mission_type = (short) type.wire()
        m.target_system = (short) target
        m.target_component = (short) RecordingChannel.GROUND_COMPONENT
        m
    }

    static MAVLinkMessage itemInt(MissionItem item, MissionType type = MissionType.MISSION) {
        item.toMessage(RecordingChannel.GROUND_SYSTEM, RecordingChannel.GROUND_COMPONENT, type)
    }

    /** The float MISSION_ITEM older vehicles answer with: latitude and longitude in degrees as floats. */
    static MAVLinkMessage floatItem(MissionItem item, MissionType type = MissionType.MISSION) {
        def m = new msg_mission_item()
        boolean global = item.frame() != MissionItem.MISSION
        m.target_system = (short) RecordingChannel.GROUND_SYSTEM
        m.target_component = (short) RecordingChannel.GROUND_COMPONENT
        m.seq = item.seq()
        m.command = item.command()
        m.frame = (short) item.frame()
        m.param1 = item.param1()
        m.param2 = item.param2()
        m.param3 = item.param3()
        m.param4 = item.param4()
        m.x = global ? (float) (item.x() * 1e-7) : (float) item.x()
        m.y = global ? (float) (item.y() * 1e-7) : (float) item.y()
        m.z = item.z()
        m.autocontinue = (short) (item.autocontinue() ? 1 : 0)
        m.mission_type = (short) type.wire()
        m
    }
}
