package dolphin.mission.transfer

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.core.ManualClock
import dolphin.core.Position
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import java.time.Duration
import java.util.concurrent.CompletableFuture
import spock.lang.Specification
import spock.lang.Unroll

import static dolphin.mission.transfer.ScriptedMissionVehicle.ack
import static dolphin.mission.transfer.ScriptedMissionVehicle.count
import static dolphin.mission.transfer.ScriptedMissionVehicle.itemInt
import static dolphin.mission.transfer.ScriptedMissionVehicle.request
import static dolphin.mission.transfer.ScriptedMissionVehicle.requestInt

/**
 * Mission upload and download (MissionTransfers, MissionUploadProtocol, MissionDownloadProtocol)
 * with no socket, no thread and no real time: the protocols send through a RecordingChannel that
 * records each message with its clock time, run their steps at once and their timeouts on a
 * ManualClock (ClockTimers). The vehicle is either the spec itself, sending one message at a time
 * ({@code channel.receive}), or a ScriptedMissionVehicle that answers as ArduPilot does, with
 * faults; its answers arrive at the clock time they were sent, so advancing the clock runs the
 * whole conversation, timeouts included, at their exact times.
 */
class MissionTransferSpec extends Specification {

    static final Position HOME = Position.fromDegrees(41.15242, -8.64096, 72)
    static final int ACCEPTED = MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
    static final int INVALID_SEQUENCE = MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE
    static final String LOST_ACK_HINT = '; the vehicle may hold the whole mission and its ACK was lost: download it to check'

    ManualClock clock = new ManualClock()
    RecordingChannel channel = new RecordingChannel(clock)
    MissionTransferConfig config = MissionTransferConfig.DEFAULT
    MissionTransfers transfers = new MissionTransfers(channel, new ClockTimers(clock), { config })
    /** When each transfer ended, in clock seconds. */
    Map<CompletableFuture<TransferResult>, Double> ends = new IdentityHashMap<>()

    def setup() {
        channel.transfers = transfers
    }

    static List<MissionItem> intended() {
        def p = { double dn, double z -> Position.fromDegrees(HOME.latitudeDegrees() + dn, HOME.longitudeDegrees(), z) }
        [
                MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, p(0, 92), 0, 0, 0, Float.NaN),
                MissionItem.at(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, p(0.0005, 102), 0, 50, 0, Float.NaN),
                MissionItem.command(3, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 0, 5, -1, 0),
                MissionItem.at(4, MAV_CMD.MAV_CMD_NAV_WAYPOINT, p(0.001, 112.5), 0, 50, 0, Float.NaN),
        ]
    }

    /** A fence of three inclusion vertices around home (numbered from 0, no home item). */
    static List<MissionItem> fence() {
        (0..2).collect { i ->
            MissionItem.at(i, MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION,
                    HOME.displace(100 * Math.cos(i * 2.1), 100 * Math.sin(i * 2.1), 0), 3, 0, 0, 0)
        }
    }

    /** The vehicle side, as ArduPilot answers, with the given faults. */
    ScriptedMissionVehicle vehicle(Collection<String> faults = [], int faultSeq = -1, int errorAck = -1) {
        def v = new ScriptedMissionVehicle(clock, channel)
        v.faults = faults as Set
        v.faultSeq = faultSeq
        v.errorAck = errorAck
        v
    }

    /** Notes when the transfer ends. */
    CompletableFuture<TransferResult> timed(CompletableFuture<TransferResult> f) {
        f.whenComplete { r, e -> ends[f] = clock.seconds() }
        f
    }

    double endOf(CompletableFuture<TransferResult> f) {
        assert f.done: 'the transfer has not ended'
        ends[f]
    }

    /** Runs the clock on by {@code seconds}: the vehicle's answers and the timeouts, in time order. */
    void run(double seconds = 60) {
        clock.advance(Duration.ofNanos(Math.round(seconds * 1e9)))
    }

    /** Runs the clock on to {@code seconds} after the start. */
    void runTo(double seconds) {
        clock.advance(Duration.ofNanos(Math.round(seconds * 1e9) - clock.nanoTime()))
    }

    List<String> sentNow() { channel.sentLines() }

    // ---- upload

    def "an upload as ArduPilot answers it: MISSION_COUNT, each item at its request, the vehicle's ACK; progress per item"() {
        given:
        def vehicle = vehicle()
        def progress = []

        when:
        def up = timed(transfers.upload().upload(intended(), MissionTransferConfig.DEFAULT, { TransferStatus s -> progress << "${s.done()}/${s.total()}" }))

        then: 'MISSION_COUNT goes out at once, on the caller\'s thread; the rest waits for the vehicle'
        channel.conversation == ['0.0 > COUNT 5']
        !up.done

        when:
        run()

        then:
        channel.conversation == ['0.0 > COUNT 5',
                                 '0.0 < REQUEST 0', '0.0 > ITEM 0', '0.0 < REQUEST 1', '0.0 > ITEM 1', '0.0 < REQUEST 2', '0.0 > ITEM 2',
                                 '0.0 < REQUEST 3', '0.0 > ITEM 3', '0.0 < REQUEST 4', '0.0 > ITEM 4', '0.0 < ACK ACCEPTED']
        with(up.get()) {
            success()
            error() == null
            items() == intended()
            resends() == 0
            ignoredAcks() == 0
        }
        endOf(up) == 0.0d
        vehicle.stored == intended()
        progress == ['0/5', '1/5', '2/5', '3/5', '4/5', '5/5']

        and: 'each item as MISSION_ITEM_INT to the vehicle\'s system and component, every field as intended'
        channel.sent.findAll { it.message instanceof com.MAVLink.common.msg_mission_item_int }.collect {
            def m = it.message as com.MAVLink.common.msg_mission_item_int
            assert m.target_system == 2 && m.target_component == 1 && m.mission_type == 0
            MissionItem.fromMessage(m)
        } == intended()
    }

    @Unroll
    def "upload with #fault: #outcome"() {
        given:
        def vehicle = vehicle(faults, faultSeq)
        def progress = []

        when:
        def up = timed(transfers.upload().upload(intended(), MissionTransferConfig.DEFAULT, { TransferStatus s -> progress << s.done() }))
        run()
        def r = up.get()

        then: 'the result, when it came, and what was sent again, at which clock time'
        r.success() == (error == null)
        r.error() == error
        endOf(up) == endsAt
        channel.repeats() == repeats
        r.resends() == resends
        r.ignoredAcks() == ignoredAcks
        progress == steps

        and: 'what the vehicle holds'
        vehicle.stored == (error == null || fault == 'no final ACK' ? intended() : [])

        where:
        fault                    | faults                | faultSeq || endsAt | repeats                                                                | resends | ignoredAcks | steps              | error
        'no fault'               | []                    | -1       || 0.0d   | []                                                                     | 0       | 0           | [0, 1, 2, 3, 4, 5] | null
        'COUNT lost once'        | ['countLost']         | -1       || 1.5d   | ['1.5 COUNT 5']                                                        | 1       | 0           | [0, 1, 2, 3, 4, 5] | null
        'item 0 lost'            | ['itemLost']          | 0        || 1.5d   | ['1.5 ITEM 0']                                                         | 1       | 0           | [0, 1, 2, 3, 4, 5] | null
        'item 2 lost'            | ['itemLost']          | 2        || 1.5d   | ['1.5 ITEM 2']                                                         | 1       | 0           | [0, 1, 2, 3, 4, 5] | null
        'last item lost'         | ['itemLost']          | 4        || 1.5d   | ['1.5 ITEM 4']                                                         | 1       | 0           | [0, 1, 2, 3, 4, 5] | null
        'requests duplicated'    | ['duplicateRequests'] | -1       || 0.0d   | ['0.0 ITEM 0', '0.0 ITEM 1', '0.0 ITEM 2', '0.0 ITEM 3', '0.0 ITEM 4'] | 5       | 4           | [0, 1, 2, 3, 4, 5] | null
        'requests reordered'     | ['reorderedRequests'] | -1       || 0.0d   | ['0.0 ITEM 1', '0.0 ITEM 2', '0.0 ITEM 3']                             | 0       | 2           | [0, 1, 2, 3, 4, 5] | null
        'MISSION_REQUEST_INT'    | ['requestInt']        | -1       || 0.0d   | []                                                                     | 0       | 0           | [0, 1, 2, 3, 4, 5] | null
        'no final ACK'           | ['noAck']             | -1       || 7.5d   | ['1.5 ITEM 4', '3.0 ITEM 4', '4.5 ITEM 4', '6.0 ITEM 4']               | 4       | 0           | [0, 1, 2, 3, 4]    | 'upload to vehicle 2 failed: no MISSION_ACK after item 4 (NAV_WAYPOINT) was sent 5 times (1.5 s apart)' + LOST_ACK_HINT
        'out-of-range request'   | ['outOfRange']        | -1       || 0.0d   | []                                                                     | 0       | 0           | [0, 1]             | 'upload to vehicle 2 failed: the vehicle requested item 7 but the mission has 5 items (0 to 4)'
        'vehicle lost at item 2' | ['silentAt']          | 2        || 7.5d   | ['1.5 ITEM 2', '3.0 ITEM 2', '4.5 ITEM 2', '6.0 ITEM 2']               | 4       | 0           | [0, 1, 2]          | 'upload to vehicle 2 failed: no MISSION_REQUEST for item 3 after item 2 (NAV_WAYPOINT) was sent 5 times (1.5 s apart) (vehicle 2 is lost: no heartbeat within 5 s)'
        outcome = error ?: 'success'
    }

    def "MISSION_REQUEST_INT requests are answered like MISSION_REQUEST, with MISSION_ITEM_INT"() {
        given:
        vehicle(['requestInt'])

        when:
        def up = transfers.upload().upload(intended())
        run()

        then:
        up.get().success()
        channel.conversation.findAll { it.contains('<') } == ['0.0 < REQUEST_INT 0', '0.0 < REQUEST_INT 1', '0.0 < REQUEST_INT 2',
                                                              '0.0 < REQUEST_INT 3', '0.0 < REQUEST_INT 4', '0.0 < ACK ACCEPTED']
        channel.sentLines() == ['0.0 COUNT 5', '0.0 ITEM 0', '0.0 ITEM 1', '0.0 ITEM 2', '0.0 ITEM 3', '0.0 ITEM 4']
    }

    def "a vehicle that never answers MISSION_COUNT: sent at 0, 1.5, 3.0, 4.5 and 6.0 s, the upload fails at 7.5 s, saying the vehicle is lost"() {
        given: 'a vehicle silent from the start: after 5 s the ground station counts it lost'
        def vehicle = vehicle()
        vehicle.silent = true

        when:
        def up = timed(transfers.upload().upload(intended()))
        runTo(1.499)

        then: 'nothing is sent again before the timeout'
        sentNow() == ['0.0 COUNT 5']

        when:
        runTo(1.5)

        then:
        sentNow() == ['0.0 COUNT 5', '1.5 COUNT 5']

        when:
        runTo(7.499)

        then: 'five sent, the last timeout still running'
        sentNow() == ['0.0 COUNT 5', '1.5 COUNT 5', '3.0 COUNT 5', '4.5 COUNT 5', '6.0 COUNT 5']
        !up.done

        when:
        runTo(7.5)
        def r = up.get()

        then:
        endOf(up) == 7.5d
        !r.success()
        r.error() == 'upload to vehicle 2 failed: no MISSION_REQUEST after 5 MISSION_COUNTs (1.5 s apart) (vehicle 2 is lost: no heartbeat within 5 s)'
        r.resends() == 4
        r.items() == []

        when: 'nothing more is sent once it failed'
        run()

        then:
        sentNow().size() == 5
    }

    @Unroll
    def "tries and timeout are configurable (#how): #error"() {
        given: 'a vehicle that does not answer, but is still heard'
        channel.receiver = null

        when:
        if (how != 'per transfer') {
            config = cfg
        }
        def up = timed(how == 'per transfer' ? transfers.upload().upload(intended(), cfg, TransferProgress.NONE)
                : transfers.upload().upload(intended()))
        run()

        then:
        sentNow() == sent
        endOf(up) == endsAt
        up.get().error() == error

        where:
        how                         | cfg                                                   || sent                                          | endsAt | error
        'per transfer'              | new MissionTransferConfig(Duration.ofMillis(500), 2)  || ['0.0 COUNT 5', '0.5 COUNT 5']                | 1.0d   | 'upload to vehicle 2 failed: no MISSION_REQUEST after 2 MISSION_COUNTs (0.5 s apart)'
        'for transfers from now on' | new MissionTransferConfig(Duration.ofMillis(2500), 3) || ['0.0 COUNT 5', '2.5 COUNT 5', '5.0 COUNT 5'] | 7.5d   | 'upload to vehicle 2 failed: no MISSION_REQUEST after 3 MISSION_COUNTs (2.5 s apart)'
        'one try'                   | new MissionTransferConfig(Duration.ofSeconds(1), 1)   || ['0.0 COUNT 5']                               | 1.0d   | 'upload to vehicle 2 failed: no MISSION_REQUEST after 1 MISSION_COUNT'
    }

    def "an item lost is sent again exactly one timeout after it was last sent; a repeated request counts as a try; the fifth unanswered send fails"() {
        given: 'the spec is the vehicle'
        def up = timed(transfers.upload().upload(intended()))

        when: 'requests for items 0 and 1, item 1 then lost'
        channel.receive(request(0))
        runTo(0.2)
        channel.receive(request(1))
        runTo(1.699)

        then:
        sentNow() == ['0.0 COUNT 5', '0.0 ITEM 0', '0.2 ITEM 1']

        when:
        runTo(1.7)

        then: 'sent again 1.5 s after it was sent'
        sentNow() == ['0.0 COUNT 5', '0.0 ITEM 0', '0.2 ITEM 1', '1.7 ITEM 1']

        when: 'the vehicle asks for item 2 at 2.0 s, and again at 2.5 s, then falls silent'
        runTo(2.0)
        channel.receive(request(2))
        runTo(2.5)
        channel.receive(request(2))
        runTo(8.499)

        then: 'the timer restarts at each send: 4.0, 5.5, 7.0 s'
        sentNow() == ['0.0 COUNT 5', '0.0 ITEM 0', '0.2 ITEM 1', '1.7 ITEM 1',
                      '2.0 ITEM 2', '2.5 ITEM 2', '4.0 ITEM 2', '5.5 ITEM 2', '7.0 ITEM 2']
        !up.done

        when:
        runTo(8.5)

        then: 'five sends of item 2 without a request for item 3'
        endOf(up) == 8.5d
        up.get().error() == 'upload to vehicle 2 failed: no MISSION_REQUEST for item 3 after item 2 (NAV_WAYPOINT) was sent 5 times (1.5 s apart)'
        up.get().resends() == 5
    }

    def "INVALID_SEQUENCE ACKs (a duplicated item on a noisy link) are ignored and counted; the upload goes on"() {
        given:
        def up = timed(transfers.upload().upload(intended().take(3)))

        when:
        channel.receive(request(0))
        channel.receive(ack(INVALID_SEQUENCE))
        runTo(1.0)
        channel.receive(request(1))
        channel.receive(ack(INVALID_SEQUENCE))
        channel.receive(request(2))

        then:
        !up.done
        sentNow() == ['0.0 COUNT 3', '0.0 ITEM 0', '1.0 ITEM 1', '1.0 ITEM 2']

        when:
        channel.receive(ack(ACCEPTED))

        then:
        with(up.get()) {
            success()
            ignoredAcks() == 2
            resends() == 0
        }
        endOf(up) == 1.0d
    }

    @Unroll
    def "error ACK #name at item 2 fails the upload at once naming the item, command and parameter"() {
        given:
        vehicle(['errorAck'], 2, result)

        when:
        def up = timed(transfers.upload().upload(intended()))
        run()

        then:
        up.get().error() == "upload to vehicle 2 failed: item 2 (NAV_WAYPOINT): MAV_MISSION_$name ($detail)".toString()
        endOf(up) == 0.0d
        channel.repeats() == []
        sentNow().last() == '0.0 ITEM 2'

        where:
        result                                             | detail
        MAV_MISSION_RESULT.MAV_MISSION_ERROR               | "frame GLOBAL_INT, params 0.0, 50.0, 0.0, NaN, x ${intended()[2].x()}, y ${intended()[2].y()}, z 102.0"
        MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED_FRAME   | 'frame GLOBAL_INT is not supported'
        MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED         | 'command 16 NAV_WAYPOINT is not supported'
        MAV_MISSION_RESULT.MAV_MISSION_NO_SPACE            | 'the vehicle has no room for 5 items'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID             | "frame GLOBAL_INT, params 0.0, 50.0, 0.0, NaN, x ${intended()[2].x()}, y ${intended()[2].y()}, z 102.0"
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1      | 'param1 = 0.0'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM2      | 'param2 = 50.0'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM3      | 'param3 = 0.0'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM4      | 'param4 = NaN'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM5_X    | 'x = 411529200 (latitude 41.152919999999995)'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM6_Y    | 'y = -86409600 (longitude -8.64096)'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM7      | 'z = 102.0'
        MAV_MISSION_RESULT.MAV_MISSION_DENIED              | 'the vehicle accepts no mission transfer from us now'
        MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED | 'the vehicle cancelled the upload'
        name = MissionUploadProtocol.resultName(result).substring('MAV_MISSION_'.length())
    }

    @Unroll
    def "#name answering MISSION_COUNT fails the upload at once: #error"() {
        given:
        vehicle(['denyCount'], -1, result)

        when:
        def up = timed(transfers.upload().upload(intended()))
        run()

        then:
        channel.conversation == ['0.0 > COUNT 5', "0.0 < ACK ${name}".toString()]
        up.get().error() == error
        endOf(up) == 0.0d

        where:
        result                                  | error
        MAV_MISSION_RESULT.MAV_MISSION_DENIED   | 'upload to vehicle 2 failed: MAV_MISSION_DENIED (the vehicle accepts no mission transfer from us now; is another ground station uploading?)'
        MAV_MISSION_RESULT.MAV_MISSION_NO_SPACE | 'upload to vehicle 2 failed: MAV_MISSION_NO_SPACE (the vehicle has no room for 5 items)'
        MAV_MISSION_RESULT.MAV_MISSION_ERROR    | 'upload to vehicle 2 failed: MAV_MISSION_ERROR (answering MISSION_COUNT 5)'
        name = MissionUploadProtocol.resultName(result) - 'MAV_MISSION_'
    }

    def "an ACCEPTED before any request is a late ACK of an earlier transfer, ignored; one before the last item was requested fails the upload"() {
        given:
        def up = timed(transfers.upload().upload(intended()))

        when:
        channel.receive(ack(ACCEPTED))

        then:
        !up.done

        when:
        channel.receive(request(0))
        channel.receive(request(1))
        channel.receive(request(2))
        channel.receive(ack(ACCEPTED))

        then:
        up.get().error() == 'upload to vehicle 2 failed: the vehicle accepted the mission after requesting only items 0 to 2 of 5'
        up.get().ignoredAcks() == 1
    }

    def "items not numbered 0, 1, 2, ... in order fail the upload before anything is sent"() {
        when:
        def up = transfers.upload().upload([intended()[0], intended()[2]])

        then:
        up.done
        up.get().error() == 'upload to vehicle 2 failed: item 1 has seq 2: items must be numbered 0, 1, 2, ... in order'
        channel.sent.empty

        when: 'the queue goes on with the next transfer'
        def next = transfers.upload().upload(intended().take(1))

        then:
        sentNow() == ['0.0 COUNT 1']
        !next.done
    }

    def "an empty upload (clear) is accepted at the vehicle's ACK to MISSION_COUNT 0"() {
        given:
        def vehicle = vehicle()
        vehicle.stored = intended()
        def progress = []

        when:
        def up = transfers.upload().upload([], MissionTransferConfig.DEFAULT, { TransferStatus s -> progress << "${s.done()}/${s.total()}" })
        run()

        then:
        up.get().success()
        channel.conversation == ['0.0 > COUNT 0', '0.0 < ACK ACCEPTED']
        vehicle.stored == []
        progress == ['0/0']
    }

    def "an empty upload whose ACK never comes fails saying so"() {
        given:
        channel.receiver = null

        when:
        def up = transfers.upload().upload([])
        run()

        then:
        up.get().error() == 'upload to vehicle 2 failed: no MISSION_ACK after 5 MISSION_COUNTs (1.5 s apart)'
    }

    // ---- download

    @Unroll
    def "download with #fault returns the vehicle's items and ends with one MISSION_ACK"() {
        given:
        def vehicle = vehicle(faults, faultSeq)
        vehicle.stored = stored
        def progress = []

        when:
        def down = timed(transfers.download().download(MissionTransferConfig.DEFAULT, { TransferStatus s -> progress << "${s.done()}/${s.total()}" }))
        run()
        def r = down.get()

        then:
        r.success()
        r.items() == stored
        r.resends() == repeats.size()
        endOf(down) == endsAt
        channel.repeats() == repeats
        sentNow().count { it.contains('REQUEST_INT') } == stored.size() + repeats.count { it.contains('REQUEST_INT') }
        sentNow().findAll { it.contains('ACK') } == ["${endsAt} ACK ACCEPTED".toString()]
        sentNow().last() == "${endsAt} ACK ACCEPTED".toString()
        progress == (0..stored.size()).collect { "$it/${stored.size()}".toString() }

        where:
        fault               | faults         | faultSeq | stored     || endsAt | repeats
        'no fault'          | []             | -1       | intended() || 0.0d   | []
        'item 3 lost'       | ['dlItemLost'] | 3        | intended() || 1.5d   | ['1.5 REQUEST_INT 3']
        'REQUEST_LIST lost' | ['listLost']   | -1       | intended() || 1.5d   | ['1.5 REQUEST_LIST']
        'an empty mission'  | []             | -1       | []         || 0.0d   | []
    }

    def "a download as ArduPilot answers it: REQUEST_LIST, the COUNT, a MISSION_REQUEST_INT per item, our ACK"() {
        given:
        vehicle().stored = intended().take(3)

        when:
        def down = transfers.download().download()
        run()

        then:
        down.get().items() == intended().take(3)
        channel.conversation == ['0.0 > REQUEST_LIST', '0.0 < COUNT 3', '0.0 > REQUEST_INT 0', '0.0 < ITEM 0', '0.0 > REQUEST_INT 1',
                                 '0.0 < ITEM 1', '0.0 > REQUEST_INT 2', '0.0 < ITEM 2', '0.0 > ACK ACCEPTED']
    }

    def "a vehicle that never answers MISSION_REQUEST_LIST fails the download after 5 of them, 1.5 s apart"() {
        given:
        vehicle().silent = true

        when:
        def down = timed(transfers.download().download())
        run()

        then:
        sentNow() == ['0.0 REQUEST_LIST', '1.5 REQUEST_LIST', '3.0 REQUEST_LIST', '4.5 REQUEST_LIST', '6.0 REQUEST_LIST']
        endOf(down) == 7.5d
        down.get().error() == 'download from vehicle 2 failed: no MISSION_COUNT after 5 MISSION_REQUEST_LISTs (1.5 s apart)' +
                ' (vehicle 2 is lost: no heartbeat within 5 s)'
        down.get().resends() == 4
    }

    def "a download's MISSION_REQUEST_INT is sent again at each timeout; five unanswered fail the download naming the item"() {
        given: 'a vehicle that never answers the request for item 3'
        def vehicle = vehicle(['dlItemNever'], 3)
        vehicle.stored = intended()

        when:
        def down = timed(transfers.download().download())
        runTo(1.499)

        then:
        sentNow() == ['0.0 REQUEST_LIST', '0.0 REQUEST_INT 0', '0.0 REQUEST_INT 1', '0.0 REQUEST_INT 2', '0.0 REQUEST_INT 3']

        when:
        run()

        then:
        channel.repeats() == ['1.5 REQUEST_INT 3', '3.0 REQUEST_INT 3', '4.5 REQUEST_INT 3', '6.0 REQUEST_INT 3']
        endOf(down) == 7.5d
        down.get().error() == 'download from vehicle 2 failed: no item 3 of 5 after 5 MISSION_REQUEST_INTs (1.5 s apart)'
        !sentNow().any { it.contains('ACK') }
    }

    def "a download ignores a second MISSION_COUNT, items it did not ask for, and INVALID_SEQUENCE ACKs (counted)"() {
        given: 'the spec is the vehicle'
        def down = timed(transfers.download().download())

        when:
        channel.receive(count(2))
        channel.receive(count(7))                   // answers a duplicated REQUEST_LIST
        channel.receive(itemInt(intended()[1]))     // not asked for
        channel.receive(ack(INVALID_SEQUENCE))      // from an earlier upload, late
        channel.receive(itemInt(intended()[0]))
        channel.receive(itemInt(intended()[0]))     // a duplicate

        then:
        sentNow() == ['0.0 REQUEST_LIST', '0.0 REQUEST_INT 0', '0.0 REQUEST_INT 1']
        !down.done

        when:
        channel.receive(itemInt(intended()[1]))

        then:
        with(down.get()) {
            items() == intended().take(2)
            ignoredAcks() == 1
            resends() == 0
        }
        sentNow().last() == '0.0 ACK ACCEPTED'
    }

    def "an error ACK fails the download, saying what it answered"() {
        when: 'DENIED answering MISSION_REQUEST_LIST (an upload from another ground station is under way)'
        def denied = transfers.download().download()
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_DENIED))

        then:
        denied.get().error() == 'download from vehicle 2 failed: MAV_MISSION_DENIED (answering MISSION_REQUEST_LIST)'

        when: 'an ERROR answering the request for item 2'
        def failed = transfers.download().download()
        channel.receive(count(5))
        channel.receive(itemInt(intended()[0]))
        channel.receive(itemInt(intended()[1]))
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR))

        then:
        failed.get().error() == 'download from vehicle 2 failed: MAV_MISSION_ERROR (answering the request for item 2 of 5)'
        sentNow() == ['0.0 REQUEST_LIST', '0.0 REQUEST_LIST', '0.0 REQUEST_INT 0', '0.0 REQUEST_INT 1', '0.0 REQUEST_INT 2']
    }

    def "a vehicle answering with the float MISSION_ITEM: its degrees become degE7 (to float precision), the rest as sent"() {
        given:
        vehicle(['floatItems']).stored = intended()

        when:
        def down = transfers.download().download()
        run()
        def items = down.get().items()

        then:
        channel.conversation.count { it.contains('< ITEM(float)') } == 5
        items.size() == 5
        [items, intended()].transpose().every { MissionItem got, MissionItem sent ->
            got.withSeq(0) == new MissionItem(0, sent.command(), sent.frame(), sent.param1(), sent.param2(), sent.param3(), sent.param4(),
                    got.x(), got.y(), sent.z(), sent.autocontinue()) &&
                    Math.abs(got.x() - sent.x()) <= 20 && Math.abs(got.y() - sent.y()) <= 20 && got.seq() == sent.seq()
        }
        items[3].x() == 0 && items[3].y() == 0
    }

    // ---- the queue

    def "one transfer at a time, in order: a download asked for during an upload runs after it and sees the new mission"() {
        given:
        def vehicle = vehicle()
        vehicle.stored = [intended()[0]]

        when:
        def up = transfers.upload().upload(intended())
        def down = transfers.download().download()
        def up2 = transfers.upload().upload(intended().take(3))

        then: 'only the first transfer has begun'
        channel.conversation == ['0.0 > COUNT 5']

        when:
        run()

        then:
        up.get().success()
        down.get().items() == intended()
        up2.get().success()
        vehicle.stored == intended().take(3)
        channel.conversation.findAll { it ==~ /.* > (COUNT|REQUEST_LIST|ACK).*/ || it ==~ /.* < ACK .*/ } ==
                ['0.0 > COUNT 5', '0.0 < ACK ACCEPTED', '0.0 > REQUEST_LIST', '0.0 > ACK ACCEPTED', '0.0 > COUNT 3', '0.0 < ACK ACCEPTED']
    }

    def "the queue moves on when a transfer fails: the next one starts at the failure's clock time"() {
        given: 'a vehicle deaf for 7.5 s'
        channel.receiver = null

        when:
        def up = timed(transfers.upload().upload(intended()))
        def down = timed(transfers.download().download())
        runTo(7.5)

        then:
        !up.get().success()
        sentNow().takeRight(2) == ['6.0 COUNT 5', '7.5 REQUEST_LIST']
        !down.done

        when: 'the vehicle answers again'
        vehicle().stored = intended()
        run()

        then:
        down.get().items() == intended()
        endOf(down) == 9.0d
    }

    def "a late ACK of the previous upload, arriving at the next one's MISSION_COUNT, is ignored and counted"() {
        given: 'the spec is the vehicle; a first upload done'
        def first = transfers.upload().upload(intended().take(2))
        channel.receive(request(0))
        channel.receive(request(1))
        channel.receive(ack(ACCEPTED))
        assert first.get().success()

        when: 'the next upload begins; the first one\'s ACK, duplicated on the link, comes again'
        def second = transfers.upload().upload(intended().take(3))
        channel.receive(ack(ACCEPTED))

        then:
        !second.done
        sentNow().last() == '0.0 COUNT 3'

        when:
        (0..2).each { channel.receive(request(it)) }
        channel.receive(ack(ACCEPTED))

        then:
        second.get().success()
        second.get().ignoredAcks() == 1
    }

    def "messages for another ground station, or of another mission type, are not the transfer's; those to all systems (0) are"() {
        given:
        def up = transfers.upload().upload(intended().take(2))

        when:
        channel.receive(request(0, MissionType.MISSION, 255))
        channel.receive(request(0, MissionType.FENCE))
        channel.receive(requestInt(0, MissionType.RALLY))

        then:
        sentNow() == ['0.0 COUNT 2']

        when:
        channel.receive(request(0, MissionType.MISSION, 0))
        channel.receive(request(1))
        channel.receive(ack(ACCEPTED, MissionType.MISSION, 255))
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_DENIED, MissionType.FENCE))

        then:
        sentNow() == ['0.0 COUNT 2', '0.0 ITEM 0', '0.0 ITEM 1']
        !up.done

        when:
        channel.receive(ack(ACCEPTED))

        then:
        up.get().success()
        up.get().ignoredAcks() == 0

        when: 'with no transfer running, the vehicle\'s mission messages are ignored'
        channel.receive(request(1))
        channel.receive(count(3))

        then:
        sentNow().size() == 3
    }

    def "a fence and rally points travel with their mission type, next to the mission; a failure names the list"() {
        given:
        def vehicle = vehicle()
        vehicle.stored = intended()
        def rally = [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_RALLY_POINT, HOME.displace(10, 10, -30), 0, 0, 0, 0)]

        when:
        def upFence = transfers.upload().upload(MissionType.FENCE, fence())
        def upRally = transfers.upload().upload(MissionType.RALLY, rally)
        def downFence = transfers.download().download(MissionType.FENCE)
        run()

        then:
        upFence.get().success()
        upRally.get().success()
        downFence.get().items() == fence()
        vehicle.lists[MissionType.FENCE] == fence()
        vehicle.lists[MissionType.RALLY] == rally
        vehicle.stored == intended()
        channel.conversation.take(8) == ['0.0 > COUNT 3 (fence)', '0.0 < REQUEST 0 (fence)', '0.0 > ITEM 0 (fence)', '0.0 < REQUEST 1 (fence)',
                                         '0.0 > ITEM 1 (fence)', '0.0 < REQUEST 2 (fence)', '0.0 > ITEM 2 (fence)', '0.0 < ACK ACCEPTED (fence)']
        channel.conversation.findAll { it.contains('> REQUEST_LIST') || it.contains('> ACK') } ==
                ['0.0 > REQUEST_LIST (fence)', '0.0 > ACK ACCEPTED (fence)']

        when: 'a failure names the list'
        channel.receiver = null
        def failed = transfers.upload().upload(MissionType.RALLY, rally)
        def failedDown = transfers.download().download(MissionType.FENCE)
        run()

        then:
        failed.get().error() == 'upload of the rally points to vehicle 2 failed: no MISSION_REQUEST after 5 MISSION_COUNTs (1.5 s apart)'
        failedDown.get().error() == 'download of the fence from vehicle 2 failed: no MISSION_COUNT after 5 MISSION_REQUEST_LISTs (1.5 s apart)'
    }

    def "a transfer that ended keeps its result: later messages and timeouts change nothing"() {
        given:
        def vehicle = vehicle()
        def up = transfers.upload().upload(intended().take(2))
        run()
        def result = up.get()

        when:
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_DENIED))
        run(20)

        then:
        up.get().is(result)
        result.success()
        vehicle.stored == intended().take(2)
        channel.sentLines() == ['0.0 COUNT 2', '0.0 ITEM 0', '0.0 ITEM 1']
    }

    // ---- verification

    def "verify compares the mission sent with the one downloaded, skipping the home item"() {
        given:
        def sent = intended()
        def home = new MissionItem(0, 16, 0, 0, 0, 0, 0, 1, 2, 584.09f, true)
        def back = [home] + sent.drop(1)

        expect:
        !MissionVerification.firstDifference(sent, back).present
        !MissionVerification.firstDifference(sent, [home] + sent.drop(1).collect {
            new MissionItem(it.seq(), it.command(), it.frame(), it.param1(), it.param2(), it.param3(), it.param4(), it.x(), it.y(),
                    it.z() + 0.005f as float, it.autocontinue())
        }).present
        MissionVerification.firstDifference(sent, back.take(3)).get() == 'the vehicle has 3 items (home included), 5 were sent'
        MissionVerification.firstDifference(sent, back.collect { it.seq() == 4 ? withZ(it, 120) : it }).get() ==
                'item 4 (NAV_WAYPOINT): z sent 112.5, vehicle has 120.0'
        MissionVerification.firstDifference(sent, back.collect { it.seq() == 2 ? withX(it, it.x() + 1) : it }).get() ==
                "item 2 (NAV_WAYPOINT): x sent ${sent[2].x()}, vehicle has ${sent[2].x() + 1}"
    }

    def "verify accepts what ArduPilot reports back: GLOBAL for GLOBAL_INT, params 2 to 4 not stored; not another altitude reference"() {
        given:
        def sent = intended()
        def asArduPilot = [sent[0]] + sent.drop(1).collect {
            new MissionItem(it.seq(), it.command(), it.frame() == 6 ? 3 : 0, it.param1(), 0, 0, 0, it.x(), it.y(), it.z(), true)
        }
        def relative = asArduPilot.collect {
            it.seq() == 2 ? new MissionItem(it.seq(), it.command(), 3, it.param1(), 0, 0, 0, it.x(), it.y(), it.z(), true) : it
        }
        def otherP1 = asArduPilot.collect {
            it.seq() == 1 ? new MissionItem(it.seq(), it.command(), it.frame(), 7, 0, 0, 0, it.x(), it.y(), it.z(), true) : it
        }

        expect:
        sent.drop(1).every { it.frame() in [2, 5] }
        !MissionVerification.firstDifference(sent, asArduPilot).present
        MissionVerification.firstDifference(sent, relative).get() == 'item 2 (NAV_WAYPOINT): frame sent GLOBAL_INT, vehicle has GLOBAL_RELATIVE_ALT'
        MissionVerification.firstDifference(sent, otherP1).get() == "item 1 (${sent[1].commandName()}): param1 sent ${sent[1].param1()}, vehicle has 7.0"
    }

    static MissionItem withZ(MissionItem i, float z) {
        new MissionItem(i.seq(), i.command(), i.frame(), i.param1(), i.param2(), i.param3(), i.param4(), i.x(), i.y(), z, i.autocontinue())
    }

    static MissionItem withX(MissionItem i, int x) {
        new MissionItem(i.seq(), i.command(), i.frame(), i.param1(), i.param2(), i.param3(), i.param4(), x, i.y(), i.z(), i.autocontinue())
    }
}
