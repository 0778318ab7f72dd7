package dolphin.mission.transfer

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.core.ManualClock
import dolphin.core.Position
import dolphin.mavlink.LinkTimeouts
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import java.time.Duration
import java.util.concurrent.CompletableFuture
import spock.lang.Specification
import spock.lang.Timeout
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
 * whole conversation, timeouts included, at their exact times. A vehicle answering at the same
 * clock time is a link with no round trip: after its first answer the timeouts are the shortest,
 * 50 ms, doubled per timeout in a row without progress.
 */
@Timeout(60)
class MissionTransferSpec extends Specification {

    static final Position HOME = Position.fromDegrees(41.15242, -8.64096, 72)
    static final int ACCEPTED = MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
    static final int INVALID_SEQUENCE = MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE

    ManualClock clock = new ManualClock()
    RecordingChannel channel = new RecordingChannel(clock)
    /** The mission protocol's own path: AUTO would add why it goes item by item to each note. */
    MissionTransferConfig config = new MissionTransferConfig(dolphin.mavlink.LinkTimeouts.DEFAULT, TransferPath.ITEMS)
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
        vehicle.stored == (error == null ? intended() : [])

        where:
        fault                  | faults                | faultSeq || endsAt | repeats                                                                | resends | ignoredAcks | steps                                 | error
        'no fault'             | []                    | -1       || 0.0d   | []                                                                     | 0       | 0           | [0, 1, 2, 3, 4, 5]                    | null
        'COUNT lost once'      | ['countLost']         | -1       || 1.5d   | ['1.5 COUNT 5']                                                        | 1       | 0           | [0, 1, 2, 3, 4, 5]                    | null
        'item 0 lost'          | ['itemLost']          | 0        || 0.05d  | ['0.05 ITEM 0']                                                        | 1       | 0           | [0, 1, 2, 3, 4, 5]                    | null
        'item 2 lost'          | ['itemLost']          | 2        || 0.05d  | ['0.05 ITEM 2']                                                        | 1       | 0           | [0, 1, 2, 3, 4, 5]                    | null
        'last item lost'       | ['itemLost']          | 4        || 0.05d  | ['0.05 ITEM 4']                                                        | 1       | 0           | [0, 1, 2, 3, 4, 5]                    | null
        'request 2 lost'       | ['requestLost']       | 2        || 0.05d  | ['0.05 ITEM 1']                                                        | 1       | 1           | [0, 1, 3, 4, 5]                       | null
        'requests duplicated'  | ['duplicateRequests'] | -1       || 0.0d   | ['0.0 ITEM 0', '0.0 ITEM 1', '0.0 ITEM 2', '0.0 ITEM 3', '0.0 ITEM 4'] | 5       | 4           | [0, 1, 2, 3, 4, 5]                    | null
        'requests reordered'   | ['reorderedRequests'] | -1       || 0.0d   | []                                                                     | 0       | 0           | [0, 1, 2, 3, 4, 5]                    | null
        'MISSION_REQUEST_INT'  | ['requestInt']        | -1       || 0.0d   | []                                                                     | 0       | 0           | [0, 1, 2, 3, 4, 5]                    | null
        'final ACK lost'       | ['ackLost']           | -1       || 0.05d  | ['0.05 ITEM 4']                                                        | 1       | 0           | [0, 1, 2, 3, 4, 0, 1, 2, 3, 4, 5, 5]  | null
        'out-of-range request' | ['outOfRange']        | -1       || 0.0d   | []                                                                     | 0       | 0           | [0, 1]                                | 'upload to vehicle 2 failed: the vehicle requested item 7 but the mission has 5 items (0 to 4)'
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

    def "a vehicle that never answers MISSION_COUNT: sent every 1.5 s (no round trip measured yet), the upload fails 10 s after it began, saying the vehicle is lost"() {
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
        runTo(9.999)

        then: 'seven sent, the give-up not yet reached'
        sentNow() == ['0.0 COUNT 5', '1.5 COUNT 5', '3.0 COUNT 5', '4.5 COUNT 5', '6.0 COUNT 5', '7.5 COUNT 5', '9.0 COUNT 5']
        !up.done

        when:
        runTo(10)
        def r = up.get()

        then:
        endOf(up) == 10.0d
        !r.success()
        r.error() == 'upload to vehicle 2 failed: no MISSION_REQUEST for item 0 in 10 s (MISSION_COUNT sent 7 times) (vehicle 2 is lost: no heartbeat within 5 s)'
        r.resends() == 6
        r.items() == []

        when: 'nothing more is sent once it failed'
        run()

        then:
        sentNow().size() == 7
    }

    @Unroll
    def "timeouts and give-up are configurable (#how): #error"() {
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
        how                         | cfg                        || sent                                          | endsAt | error
        'per transfer'              | config(50, 500, 1000)      || ['0.0 COUNT 5', '0.5 COUNT 5']                | 1.0d   | 'upload to vehicle 2 failed: no MISSION_REQUEST for item 0 in 1 s (MISSION_COUNT sent 2 times)'
        'for transfers from now on' | config(100, 2500, 6000)    || ['0.0 COUNT 5', '2.5 COUNT 5', '5.0 COUNT 5'] | 6.0d   | 'upload to vehicle 2 failed: no MISSION_REQUEST for item 0 in 6 s (MISSION_COUNT sent 3 times)'
        'give-up = longest timeout' | config(1000, 1000, 1000)   || ['0.0 COUNT 5']                               | 1.0d   | 'upload to vehicle 2 failed: no MISSION_REQUEST for item 0 in 1 s (MISSION_COUNT sent 1 time)'
    }

    static MissionTransferConfig config(long minMs, long maxMs, long giveUpMs) {
        new MissionTransferConfig(new LinkTimeouts(Duration.ofMillis(minMs), Duration.ofMillis(maxMs), Duration.ofMillis(giveUpMs)),
                TransferPath.ITEMS)
    }

    def "the timeout follows the measured round trip; a missing request brings the item again and the next; the request for that next one, in flight, is not answered"() {
        given: 'the spec is the vehicle, 200 ms away (round trip)'
        def statuses = []
        def up = timed(transfers.upload().upload(intended(), config, { TransferStatus s -> statuses << s }))

        when: 'COUNT answered after 200 ms: round trip 200 ms, deviation 100 ms, timeout 600 ms'
        runTo(0.2)
        channel.receive(request(0))

        then:
        channel.roundTrip.smoothedNanos() == 200_000_000
        channel.roundTrip.timeoutNanos(0) == 600_000_000

        when: 'item 0 answered after 200 ms: deviation 75 ms, timeout 500 ms; item 1 then lost'
        runTo(0.4)
        channel.receive(request(1))
        runTo(0.899)

        then:
        channel.roundTrip.timeoutNanos(0) == 500_000_000
        sentNow() == ['0.0 COUNT 5', '0.2 ITEM 0', '0.4 ITEM 1']

        when: 'no request for item 2 within 500 ms'
        runTo(0.9)

        then: 'item 1 again and item 2, which ArduPilot takes as the one it expects'
        sentNow() == ['0.0 COUNT 5', '0.2 ITEM 0', '0.4 ITEM 1', '0.9 ITEM 1', '0.9 ITEM 2']

        when: 'the vehicle got both: its request for item 2 comes while item 2 is in flight, then the one for item 3'
        runTo(1.05)
        channel.receive(request(2))

        then: 'not answered'
        sentNow().size() == 5

        when:
        runTo(1.1)
        channel.receive(request(3))

        then: 'item 1 went twice: its answer is no sample (Karn); item 2 went once: 200 ms, timeout 425 ms'
        sentNow().last() == '1.1 ITEM 3'
        channel.roundTrip.samples() == 3
        channel.roundTrip.timeoutNanos(0) == 425_000_000

        when: 'the vehicle falls silent for a while'
        runTo(3.874)

        then: 'items 3 and 4 again after 425 ms, then after twice and four times that (backed off), at most 1.5 s'
        channel.repeats() == ['0.9 ITEM 1', '1.525 ITEM 3', '2.375 ITEM 3', '2.375 ITEM 4']
        sentNow().takeRight(4) == ['1.525 ITEM 3', '1.525 ITEM 4', '2.375 ITEM 3', '2.375 ITEM 4']

        when:
        runTo(3.875)

        then:
        sentNow().takeRight(2) == ['3.875 ITEM 3', '3.875 ITEM 4']

        when: 'the vehicle asks for item 4 (in flight: not answered) and accepts it'
        runTo(4.0)
        channel.receive(request(4))
        channel.receive(ack(ACCEPTED))

        then:
        with(up.get()) {
            success()
            !verified()
            resends() == 6
            ignoredAcks() == 0
        }
        endOf(up) == 4.0d
        sentNow().size() == 12

        and: 'progress as items advance, with the resends so far'
        statuses.collect { "${it.done()}/${it.total()} ${it.resends()}".toString() } ==
                ['0/5 0', '1/5 0', '2/5 1', '3/5 1', '4/5 6', '5/5 6']
        statuses.every { it.path() == TransferPath.ITEMS && it.upload() }
    }

    def "a vehicle that keeps asking for the next item, however slowly, never makes the upload give up"() {
        given: 'the spec is the vehicle: each answer 9 s after the last, each within the 10 s without progress'
        def up = timed(transfers.upload().upload(intended().take(3)))

        when:
        [0, 1, 2].each { seq ->
            runTo(9.0 * (seq + 1))
            channel.receive(request(seq))
        }
        runTo(36)
        channel.receive(ack(ACCEPTED))

        then: '36 s, while five sends of one message without an answer (7.5 s) failed it before'
        up.get().success()
        endOf(up) == 36.0d
        sentNow().count { it.endsWith('COUNT 3') } == 7
    }

    def "a vehicle lost at item 2: items 2 and 3 again at each timeout, backed off twice, and the upload fails 10 s after the request for item 2"() {
        given:
        vehicle(['silentAt'], 2)

        when:
        def up = timed(transfers.upload().upload(intended()))
        run()

        then:
        endOf(up) == 10.0d
        up.get().error() == 'upload to vehicle 2 failed: no MISSION_REQUEST for item 3 in 10 s (item 2 sent 52 times) (vehicle 2 is lost: no heartbeat within 5 s)'
        def times = channel.repeats().findAll { it.endsWith('ITEM 2') }*.split(' ')*.getAt(0)
        times.take(5) == ['0.05', '0.15', '0.35', '0.55', '0.75']
        times.size() == 51
        times.last() == '9.95'
        up.get().resends() == 51 + 50
    }

    static final String READ_BACK = 'the final ACK was lost; the vehicle holds the whole mission, read back'

    def "a MAV_MISSION_ERROR after the last item (its final ACK lost, the item repeated) is settled by reading the mission back: equal, verified"() {
        given:
        def vehicle = vehicle(['ackLost'])

        when:
        def up = timed(transfers.upload().upload(intended()))
        run()
        def r = up.get()

        then: 'one transfer: the upload, then the download inside it'
        channel.conversation.drop(10) == ['0.0 > ITEM 4', '0.05 > ITEM 4', '0.05 < ACK ERROR', '0.05 > REQUEST_LIST', '0.05 < COUNT 5',
                                          '0.05 > REQUEST_INT 0', '0.05 > REQUEST_INT 1', '0.05 > REQUEST_INT 2', '0.05 > REQUEST_INT 3',
                                          '0.05 < ITEM 0', '0.05 > REQUEST_INT 4', '0.05 < ITEM 1', '0.05 < ITEM 2', '0.05 < ITEM 3',
                                          '0.05 < ITEM 4', '0.05 > ACK ACCEPTED']
        with(r) {
            success()
            verified()
            note() == READ_BACK
            items() == intended()
            resends() == 1
        }
        endOf(up) == 0.05d
        vehicle.stored == intended()
    }

    def "a refused last item (MAV_MISSION_ERROR) is settled the same way: the list read back differs, the upload fails saying both"() {
        given:
        def vehicle = vehicle(['errorAck'], 4, MAV_MISSION_RESULT.MAV_MISSION_ERROR)

        when:
        def up = timed(transfers.upload().upload(intended()))
        run()
        def r = up.get()

        then:
        !r.success()
        r.error().startsWith('upload to vehicle 2 failed: item 4 (NAV_WAYPOINT): MAV_MISSION_ERROR (frame GLOBAL_INT, params ')
        r.error().endsWith('; read back, the vehicle has 0 items (home included), 5 were sent')
        endOf(up) == 0.0d
        sentNow().takeRight(2) == ['0.0 REQUEST_LIST', '0.0 ACK ACCEPTED']
    }

    def "silence after the last item until the give-up is settled by reading back: the vehicle had it all, verified"() {
        given: 'the final ACK and the answers to the repeated last item never arrive'
        vehicle(['noAck'])

        when:
        def up = timed(transfers.upload().upload(intended()))
        run()
        def r = up.get()

        then: 'the last item again at each timeout, then at 10 s the read-back'
        channel.repeats().findAll { it.endsWith('ITEM 4') }.size() == 51
        with(r) {
            success()
            verified()
            note() == READ_BACK
            resends() == 51
        }
        endOf(up) == 10.0d
    }

    def "silence after the last item, and the read-back failing too: the upload fails with both reasons"() {
        given: 'the vehicle takes the last item and falls silent'
        def vehicle = vehicle(['silentAfterLast'])

        when:
        def up = timed(transfers.upload().upload(intended()))
        run()

        then:
        up.get().error() == 'upload to vehicle 2 failed: no MISSION_ACK in 10 s (item 4 sent 52 times); reading the mission back' +
                ' failed: no MISSION_COUNT in 10 s (MISSION_REQUEST_LIST sent 52 times) (vehicle 2 is lost: no heartbeat within 5 s)'
        endOf(up) == 20.0d
        vehicle.stored == intended()
    }

    def "INVALID_SEQUENCE ACKs (a duplicated item on a noisy link) are ignored and counted; the upload goes on"() {
        given:
        def up = timed(transfers.upload().upload(intended().take(3)))

        when: 'answers 200 ms after each send (timeout 600 ms, then 500 ms)'
        runTo(0.2)
        channel.receive(request(0))
        channel.receive(ack(INVALID_SEQUENCE))
        runTo(0.4)
        channel.receive(request(1))
        channel.receive(ack(INVALID_SEQUENCE))
        channel.receive(request(2))

        then:
        !up.done
        sentNow() == ['0.0 COUNT 3', '0.2 ITEM 0', '0.4 ITEM 1', '0.4 ITEM 2']

        when:
        channel.receive(ack(ACCEPTED))

        then:
        with(up.get()) {
            success()
            ignoredAcks() == 2
            resends() == 0
        }
        endOf(up) == 0.4d
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
        name = MissionUploadProtocol.resultName(result) - 'MAV_MISSION_'
    }

    def "a MAV_MISSION_ERROR before any request may answer the previous upload's last item, still on the link: the first is ignored, a second fails"() {
        given:
        def up = timed(transfers.upload().upload(intended()))

        when: 'it arrives 30 ms after MISSION_COUNT, before MISSION_COUNT could reach the vehicle over a radio'
        clock.advance(Duration.ofMillis(30))
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR))

        then:
        !up.done

        when: 'a vehicle that refuses MISSION_COUNT with MAV_MISSION_ERROR answers the resent one so too'
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR))

        then:
        up.get().error() == 'upload to vehicle 2 failed: MAV_MISSION_ERROR (answering MISSION_COUNT 5)'
        up.get().ignoredAcks() == 1
    }

    def "after a stale MAV_MISSION_ERROR the upload goes on as usual"() {
        given:
        def up = transfers.upload().upload(intended().take(3))

        when:
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR))
        (0..2).each { channel.receive(request(it)) }
        channel.receive(ack(ACCEPTED))

        then:
        up.get().success()
        up.get().ignoredAcks() == 1
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
        up.get().error() == 'upload to vehicle 2 failed: no MISSION_ACK in 10 s (MISSION_COUNT sent 7 times)'
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
        'item 3 lost'       | ['dlItemLost'] | 3        | intended() || 0.05d  | ['0.05 REQUEST_INT 3']
        'REQUEST_LIST lost' | ['listLost']   | -1       | intended() || 1.5d   | ['1.5 REQUEST_LIST']
        'an empty mission'  | []             | -1       | []         || 0.0d   | []
    }

    def "a download as ArduPilot answers it: REQUEST_LIST, the COUNT, a MISSION_REQUEST_INT per item, four at most outstanding, our ACK"() {
        given:
        vehicle().stored = intended()

        when:
        def down = transfers.download().download()
        run()

        then:
        down.get().items() == intended()
        channel.conversation == ['0.0 > REQUEST_LIST', '0.0 < COUNT 5', '0.0 > REQUEST_INT 0', '0.0 > REQUEST_INT 1', '0.0 > REQUEST_INT 2',
                                 '0.0 > REQUEST_INT 3', '0.0 < ITEM 0', '0.0 > REQUEST_INT 4', '0.0 < ITEM 1', '0.0 < ITEM 2', '0.0 < ITEM 3',
                                 '0.0 < ITEM 4', '0.0 > ACK ACCEPTED']
    }

    def "a vehicle that never answers MISSION_REQUEST_LIST fails the download 10 s on, after 7 of them, 1.5 s apart"() {
        given:
        vehicle().silent = true

        when:
        def down = timed(transfers.download().download())
        run()

        then:
        sentNow() == ['0.0 REQUEST_LIST', '1.5 REQUEST_LIST', '3.0 REQUEST_LIST', '4.5 REQUEST_LIST', '6.0 REQUEST_LIST',
                      '7.5 REQUEST_LIST', '9.0 REQUEST_LIST']
        endOf(down) == 10.0d
        down.get().error() == 'download from vehicle 2 failed: no MISSION_COUNT in 10 s (MISSION_REQUEST_LIST sent 7 times)' +
                ' (vehicle 2 is lost: no heartbeat within 5 s)'
        down.get().resends() == 6
    }

    def "a download's MISSION_REQUEST_INT is sent again at each timeout, backed off; 10 s without the item fail the download naming it"() {
        given: 'a vehicle that never answers the request for item 3'
        def vehicle = vehicle(['dlItemNever'], 3)
        vehicle.stored = intended()

        when:
        def down = timed(transfers.download().download())
        runTo(0.049)

        then:
        sentNow() == ['0.0 REQUEST_LIST', '0.0 REQUEST_INT 0', '0.0 REQUEST_INT 1', '0.0 REQUEST_INT 2', '0.0 REQUEST_INT 3',
                      '0.0 REQUEST_INT 4']

        when:
        run()

        then: '50 ms (the shortest), doubled per timeout in a row, twice at most'
        channel.repeats().take(5) == ['0.05', '0.15', '0.35', '0.55', '0.75'].collect { "$it REQUEST_INT 3".toString() }
        channel.repeats().size() == 51
        endOf(down) == 10.0d
        down.get().error() == 'download from vehicle 2 failed: no item 3 of 5 in 10 s (MISSION_REQUEST_INT sent 52 times)'
        !sentNow().any { it.contains('ACK') }
    }

    def "a download ignores a second MISSION_COUNT, items it did not ask for, duplicates and INVALID_SEQUENCE ACKs (counted); items may come in any order"() {
        given: 'the spec is the vehicle'
        def down = timed(transfers.download().download())

        when:
        channel.receive(count(2))
        channel.receive(count(7))                   // answers a duplicated REQUEST_LIST
        channel.receive(itemInt(intended()[3]))     // not asked for
        channel.receive(ack(INVALID_SEQUENCE))      // from an earlier upload, late
        channel.receive(itemInt(intended()[1]))     // before item 0
        channel.receive(itemInt(intended()[1]))     // a duplicate

        then:
        sentNow() == ['0.0 REQUEST_LIST', '0.0 REQUEST_INT 0', '0.0 REQUEST_INT 1']
        !down.done

        when:
        channel.receive(itemInt(intended()[0]))

        then:
        with(down.get()) {
            items() == intended().take(2)
            ignoredAcks() == 1
            resends() == 0
        }
        sentNow().last() == '0.0 ACK ACCEPTED'
    }

    def "a download with four requests outstanding: a lost item's request goes again at the timeout, alone; the window slides past it"() {
        given: 'the spec is the vehicle, 100 ms away'
        def down = timed(transfers.download().download())
        runTo(0.1)
        channel.receive(count(6))

        when: 'items 1 and 2 come back, out of order; item 0 is lost'
        runTo(0.2)
        channel.receive(itemInt(intended()[2]))
        channel.receive(itemInt(intended()[1]))

        then: 'two more requested as two came'
        sentNow() == ['0.0 REQUEST_LIST', '0.1 REQUEST_INT 0', '0.1 REQUEST_INT 1', '0.1 REQUEST_INT 2', '0.1 REQUEST_INT 3',
                      '0.2 REQUEST_INT 4', '0.2 REQUEST_INT 5']

        when: 'item 3 comes: four samples of 100 ms, timeout 184 ms; it passes for item 0 at 0.284 s'
        channel.receive(itemInt(intended()[3]))
        runTo(0.35)

        then: 'request 0 goes again, alone: 4 and 5 are not yet due'
        channel.repeats() == ['0.284 REQUEST_INT 0']

        when:
        channel.receive(itemInt(intended()[0]))
        channel.receive(itemInt(intended()[4]))
        channel.receive(itemInt(intended()[4]))
        channel.receive(itemInt(MissionItem.command(5, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 0, 3, -1, 0)))

        then:
        with(down.get()) {
            items()*.seq() == [0, 1, 2, 3, 4, 5]
            items().take(5) == intended()
            resends() == 1
        }
        sentNow().last() == '0.35 ACK ACCEPTED'
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
        sentNow() == ['0.0 REQUEST_LIST', '0.0 REQUEST_LIST', '0.0 REQUEST_INT 0', '0.0 REQUEST_INT 1', '0.0 REQUEST_INT 2',
                      '0.0 REQUEST_INT 3', '0.0 REQUEST_INT 4']
    }

    def "a MAV_MISSION_ERROR before the count answers an item the last upload repeated after its end (PX4, ArduPilot): ignored, the download goes on"() {
        when:
        def down = transfers.download().download()
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR))
        channel.receive(count(2))
        channel.receive(itemInt(intended()[0]))
        channel.receive(itemInt(intended()[1]))

        then:
        down.get().success()
        down.get().items() == intended().take(2)
        down.get().ignoredAcks() == 1
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
        given: 'a vehicle deaf for 10 s'
        channel.receiver = null

        when:
        def up = timed(transfers.upload().upload(intended()))
        def down = timed(transfers.download().download())
        runTo(10)

        then:
        !up.get().success()
        sentNow().takeRight(2) == ['9.0 COUNT 5', '10.0 REQUEST_LIST']
        !down.done

        when: 'the vehicle answers again'
        vehicle().stored = intended()
        run()

        then:
        down.get().items() == intended()
        endOf(down) == 11.5d
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
        failed.get().error() == 'upload of the rally points to vehicle 2 failed: no MISSION_REQUEST for item 0 in 10 s (MISSION_COUNT sent 52 times)'
        failedDown.get().error() == 'download of the fence from vehicle 2 failed: no MISSION_COUNT in 10 s (MISSION_REQUEST_LIST sent 52 times)'
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
