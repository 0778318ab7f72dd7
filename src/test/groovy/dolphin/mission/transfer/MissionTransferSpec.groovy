package dolphin.mission.transfer

import dolphin.mission.model.MissionItem
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.core.Position
import dolphin.core.SystemClock
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.MAVLinkNode
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll
import spock.util.concurrent.PollingConditions

import java.util.concurrent.TimeUnit

/**
 * Mission upload and download against a scripted vehicle over real UDP on loopback. The clock runs
 * ten times faster than real time, so the 1.5 s timeout is 150 ms of real time.
 */
@Timeout(60)
class MissionTransferSpec extends Specification {

    static final Position HOME = Position.fromDegrees(41.15242, -8.64096, 72)

    @AutoCleanup
    MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), new SystemClock(10))
    @AutoCleanup
    FakeMissionVehicle vehicle

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

    MAVLinkNode connect(Set<String> faults = [] as Set, int faultSeq = -1, int errorAck = -1) {
        comms.start()
        vehicle = new FakeMissionVehicle(2, comms.links()[0].localPort())
        vehicle.faults = faults
        vehicle.faultSeq = faultSeq
        vehicle.errorAck = errorAck
        vehicle.start()
        new PollingConditions(timeout: 10).eventually { assert comms.node('2') != null }
        comms.node('2')
    }

    static TransferResult await(java.util.concurrent.CompletableFuture<TransferResult> f) {
        f.get(30, TimeUnit.SECONDS)
    }

    @Unroll
    def "upload with #fault: #outcome"() {
        given:
        def node = connect(faults as Set, faultSeq)
        def progress = new java.util.concurrent.CopyOnWriteArrayList()

        when:
        def r = await(node.uploadProtocol.upload(intended(), MissionTransferConfig.DEFAULT, { d, t -> progress << d }))

        then:
        r.success() == (outcome == 'success')
        outcome == 'success' ? vehicle.stored == intended() : r.error().contains(outcome)
        !r.success() || progress.last() == 5
        r.resends() >= minResends
        r.ignoredAcks() >= minIgnored

        where:
        fault                 | faults                  | faultSeq | minResends | minIgnored | outcome
        'no fault'            | []                      | -1       | 0          | 0          | 'success'
        'COUNT lost once'     | ['countLost']           | -1       | 1          | 0          | 'success'
        'item 0 lost'         | ['itemLost']            | 0        | 1          | 0          | 'success'
        'item 2 lost'         | ['itemLost']            | 2        | 1          | 0          | 'success'
        'last item lost'      | ['itemLost']            | 4        | 1          | 0          | 'success'
        'requests duplicated' | ['duplicateRequests']   | -1       | 4          | 4          | 'success'
        'requests reordered'  | ['reorderedRequests']   | -1       | 0          | 2          | 'success'
        'MISSION_REQUEST_INT' | ['requestInt']          | -1       | 0          | 0          | 'success'
        'no final ACK'        | ['noAck']               | -1       | 4          | 0          | 'upload to vehicle 2 failed: no MISSION_ACK after item 4 (NAV_WAYPOINT) was sent 5 times (1.5 s apart)'
        'out-of-range request'| ['outOfRange']          | -1       | 0          | 0          | 'upload to vehicle 2 failed: the vehicle requested item 7 but the mission has 5 items (0 to 4)'
        'vehicle lost at item 2' | ['silentAt']         | 2        | 4          | 0          | 'upload to vehicle 2 failed: no MISSION_REQUEST for item 3 after item 2 (NAV_WAYPOINT) was sent 5 times (1.5 s apart)'
    }

    def "a vehicle that never answers MISSION_COUNT fails the upload after 5 tries"() {
        given:
        def node = connect()
        vehicle.silent = true

        when:
        def r = await(node.uploadProtocol.upload(intended()))

        then:
        !r.success()
        r.error().startsWith('upload to vehicle 2 failed: no MISSION_REQUEST after 5 MISSION_COUNTs (1.5 s apart)')
        r.resends() == 4
    }

    def "tries and timeout are configurable"() {
        given:
        def node = connect()
        vehicle.silent = true

        when:
        def r = await(node.uploadProtocol.upload(intended(), new MissionTransferConfig(java.time.Duration.ofMillis(500), 2),
                TransferProgress.NONE))

        then:
        r.error().startsWith('upload to vehicle 2 failed: no MISSION_REQUEST after 2 MISSION_COUNTs (0.5 s apart)')
    }

    @Unroll
    def "error ACK #name at item 2 fails the upload naming the item, command and parameter"() {
        given:
        def node = connect(['errorAck'] as Set, 2, result)

        when:
        def r = await(node.uploadProtocol.upload(intended()))

        then:
        !r.success()
        r.error().startsWith("upload to vehicle 2 failed: item 2 (NAV_WAYPOINT): MAV_MISSION_$name (")
        r.error().contains(detail)

        where:
        result                                            | detail
        MAV_MISSION_RESULT.MAV_MISSION_ERROR              | 'params 0.0, 50.0, 0.0, NaN'
        MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED_FRAME  | 'frame GLOBAL_INT is not supported'
        MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED        | 'command 16 NAV_WAYPOINT is not supported'
        MAV_MISSION_RESULT.MAV_MISSION_NO_SPACE           | 'no room for 5 items'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID            | 'z 102.0'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1     | 'param1 = 0.0'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM2     | 'param2 = 50.0'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM3     | 'param3 = 0.0'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM4     | 'param4 = NaN'
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM5_X   | "x = ${intended()[2].x()}"
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM6_Y   | "y = ${intended()[2].y()}"
        MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM7     | '(z = 102.0)'
        MAV_MISSION_RESULT.MAV_MISSION_DENIED             | 'accepts no mission transfer'
        MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED| 'cancelled the upload'
        name = MissionUploadProtocol.resultName(result).substring('MAV_MISSION_'.length())
    }

    def "an empty upload (clear) is accepted"() {
        given:
        def node = connect()
        vehicle.stored = intended()

        when:
        def r = await(node.uploadProtocol.upload([]))

        then:
        r.success()
        vehicle.stored == []
    }

    @Unroll
    def "download with #fault returns the vehicle's items and ends with MISSION_ACK"() {
        given:
        def node = connect(faults as Set, faultSeq)
        vehicle.stored = stored

        when:
        def r = await(node.downloadProtocol.download())

        then:
        r.success()
        r.items() == stored
        new PollingConditions(timeout: 5).eventually { assert vehicle.received('ACK 0').size() == 1 }
        vehicle.received('REQUEST_INT').size() == stored.size() + extraRequests

        where:
        fault                 | faults         | faultSeq | stored     | extraRequests
        'no fault'            | []             | -1       | intended() | 0
        'item 3 lost'         | ['dlItemLost'] | 3        | intended() | 1
        'REQUEST_LIST lost'   | ['listLost']   | -1       | intended() | 0
        'an empty mission'    | []             | -1       | []         | 0
    }

    def "a vehicle that never answers MISSION_REQUEST_LIST fails the download"() {
        given:
        def node = connect()
        vehicle.silent = true

        when:
        def r = await(node.downloadProtocol.download())

        then:
        r.error().startsWith('download from vehicle 2 failed: no MISSION_COUNT after 5 MISSION_REQUEST_LISTs (1.5 s apart)')
    }

    def "one transfer at a time: a download started with an upload runs after it, and sees the new mission"() {
        given:
        def node = connect()
        vehicle.stored = [intended()[0]]

        when:
        def up = node.uploadProtocol.upload(intended())
        def down = node.downloadProtocol.download()
        def up2 = node.uploadProtocol.upload(intended().take(3))

        then:
        await(up).success()
        await(down).items() == intended()
        await(up2).success()
        vehicle.stored == intended().take(3)
        def order = vehicle.log.findAll { it ==~ /in (COUNT|REQUEST_LIST).*/ || it == 'out ACK 0' || it == 'in ACK 0' }
        order == ['in COUNT 5', 'out ACK 0', 'in REQUEST_LIST', 'in ACK 0', 'in COUNT 3', 'out ACK 0']
    }

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
