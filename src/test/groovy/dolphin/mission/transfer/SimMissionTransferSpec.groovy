package dolphin.mission.transfer

import dolphin.mission.flight.MissionService
import dolphin.testing.MissionLayer
import dolphin.mission.model.Fence
import dolphin.mission.model.FenceRegion
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import dolphin.mission.model.RallyPoints
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.FleetHarness
import dolphin.mavlink.LinkTimeouts
import dolphin.sim.FaultModel
import dolphin.sim.SimOptions
import dolphin.sim.VehicleKind
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

import java.time.Duration
import java.util.concurrent.TimeUnit

/** Mission upload, download and verify against simulated vehicles (dolphin.sim), with random loss both ways. */
@Timeout(120)
class SimMissionTransferSpec extends Specification {

    @AutoCleanup
    FleetHarness h = new FleetHarness()

    static List<MissionItem> missionAround(Position home, int points, double alt) {
        def items = [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, home, 0, 0, 0, 0)]
        items << MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, Position.fromDegrees(home.latitudeDegrees(), home.longitudeDegrees(),
                home.hae() + alt), 0, 0, 0, Float.NaN)
        (2..points).each { i ->
            items << MissionItem.at(i, MAV_CMD.MAV_CMD_NAV_WAYPOINT, Position.fromDegrees(home.latitudeDegrees() + i * 1e-4,
                    home.longitudeDegrees() - i * 1e-4, home.hae() + alt + i), 0, 2, 0, Float.NaN)
        }
        items
    }

    /** A square inclusion fence of 600 m around home, an exclusion circle and a return point. */
    static Fence fenceAround(Position home) {
        Fence.of([new FenceRegion.Polygon(true, [home.displace(-300, -300, 0), home.displace(-300, 300, 0),
                                                 home.displace(300, 300, 0), home.displace(300, -300, 0)]),
                  new FenceRegion.Circle(false, home.displace(100, 0, 0), 25.5)],
                home.displace(0, 10, -30), MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT)
    }

    /** Two rally points near home, one at a height of decimetres. */
    static RallyPoints rallyAround(Position home) {
        RallyPoints.at([home.displace(50, 50, -40.3), home.displace(-50, 50, -45)])
    }

    @Unroll
    def "#rounds uploads with #lossPct% loss both ways each complete and verify by download"() {
        given:
        def fleet = h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT, loss == 0 ? FaultModel.NONE : FaultModel.loss(loss, 7))
        h.eventually(20) { assert h.node('1')?.home != null }
        def node = h.node('1')
        MissionService.of(h.comms).transferConfig = new MissionTransferConfig(LinkTimeouts.DEFAULT, TransferPath.ITEMS)

        expect: 'a lost final ACK is settled inside the upload, which reads the mission back'
        (1..rounds).each { round ->
            def items = missionAround(node.home, 4 + round, 20 + round)
            def up = MissionLayer.uploads(node).upload(items).get(60, TimeUnit.SECONDS)
            assert up.success(): up.error()
            def down = MissionLayer.downloads(node).download().get(60, TimeUnit.SECONDS)
            assert down.success(): down.error()
            String diff = MissionVerification.firstDifference(items, down.items()).orElse(null)
            assert diff == null
            assert fleet.vehicle(1).mission().size() == items.size()
        }

        where: // giving up after 10 s without progress is negligible at 10 % (at least six sends, backed off
        // to 1.5 s, each exchange lost with 19 %: 0.19^6 = 5e-5 per item); so is the vehicle's 8 s without an item
        loss | rounds
        0    | 3
        0.1  | 5
        lossPct = (int) (loss * 100)
    }

    def "a fence and rally points go up with their own mission_type, come back as ArduPilot stores them, and leave the mission alone"() {
        given:
        def fleet = h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT, FaultModel.NONE)
        h.eventually(20) { assert h.node('1')?.home != null }
        def node = h.node('1')
        Position home = node.home
        def mission = missionAround(home, 3, 20)
        Fence fence = fenceAround(home)
        RallyPoints rally = rallyAround(home)

        when:
        def up = [MissionLayer.uploads(node).upload(mission), MissionLayer.uploads(node).upload(MissionType.FENCE, fence.items()),
                  MissionLayer.uploads(node).upload(MissionType.RALLY, rally.items())]*.get(30, TimeUnit.SECONDS)
        def downFence = MissionLayer.downloads(node).download(MissionType.FENCE).get(30, TimeUnit.SECONDS)
        def downRally = MissionLayer.downloads(node).download(MissionType.RALLY).get(30, TimeUnit.SECONDS)
        def downMission = MissionLayer.downloads(node).download().get(30, TimeUnit.SECONDS)

        then:
        up.every { it.success() }
        MissionVerification.firstDifference(MissionType.FENCE, fence.items(), downFence.items()) == Optional.empty()
        MissionVerification.firstDifference(MissionType.RALLY, rally.items(), downRally.items()) == Optional.empty()
        MissionVerification.firstDifference(mission, downMission.items()) == Optional.empty()
        downFence.items()*.frame().toUnique() == [MAV_FRAME.MAV_FRAME_GLOBAL] // ArduPilot keeps no fence frame or altitude
        downFence.items()*.z().toUnique() == [0f]
        fleet.vehicle(1).fence() == fence
        fleet.vehicle(1).rallyPoints() == rally
        fleet.vehicle(1).mission().size() == mission.size()

        when: 'a fence whose polygon stops short is refused as a whole, and the stored one stays'
        def broken = MissionLayer.uploads(node).upload(MissionType.FENCE, fence.items().take(2)).get(30, TimeUnit.SECONDS)

        then:
        !broken.success()
        broken.error().startsWith('upload of the fence to vehicle 1 failed: item 1 (NAV_FENCE_POLYGON_VERTEX_INCLUSION): MAV_MISSION_ERROR')
        fleet.vehicle(1).fence() == fence
    }

    @Unroll
    def "over FTP to a simulated #kind, the mission, fence and rally points are verified by the vehicle's CRC of its copy: nothing is read back"() {
        given:
        h.fleet(1, kind, 1, SimOptions.DEFAULT, FaultModel.NONE)
        h.eventually(20) { assert h.node('1')?.home != null && h.node('1').capabilities().present }
        def node = h.node('1')
        Position home = node.home
        List<Integer> opcodes = new java.util.concurrent.CopyOnWriteArrayList<>()
        h.comms.addObserver { boolean incoming, link, frame ->
            if (!incoming && frame.message() instanceof com.MAVLink.common.msg_file_transfer_protocol) {
                opcodes << (frame.message().payload[3] & 0xff)
            }
        }
        Fence fence = fenceAround(home)
        RallyPoints rally = rallyAround(home)

        when:
        def up = [MissionLayer.uploads(node).upload(missionAround(home, 8, 30.123)),
                  MissionLayer.uploads(node).upload(MissionType.FENCE, fence.items()),
                  MissionLayer.uploads(node).upload(MissionType.RALLY, rally.items())]*.get(30, TimeUnit.SECONDS)

        then:
        up.every { it.success() && it.verified() && it.note() == 'over FTP' }
        opcodes.count { it == 14 } == 3   // CalcFileCRC32
        opcodes.count { it == 4 } == 0    // OpenFileRO: no read-back over the link

        where:
        kind << [VehicleKind.COPTER, VehicleKind.PLANE]
    }

    def "with 30% loss both ways a download always returns what the vehicle holds, whatever became of the upload before it"() {
        given: 'the vehicle may cancel an upload after 8 s without an item; the download gives up only after 10 s without progress'
        def fleet = h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT, FaultModel.loss(0.3, 7))
        h.eventually(20) { assert h.node('1')?.home != null }
        def node = h.node('1')
        MissionService.of(h.comms).transferConfig = new MissionTransferConfig(LinkTimeouts.DEFAULT, TransferPath.ITEMS)

        expect:
        (1..4).each { round ->
            MissionLayer.uploads(node).upload(missionAround(node.home, 4 + round, 20 + round)).get(90, TimeUnit.SECONDS)
            def down = MissionLayer.downloads(node).download().get(90, TimeUnit.SECONDS)
            assert down.success(): down.error()
            assert MissionVerification.firstDifference(fleet.vehicle(1).mission(), down.items()).orElse(null) == null
        }
    }

    def "a script downloads a vehicle's mission with downloadMission"() {
        given:
        h.fleet(1)
        h.eventually(20) { assert h.node('1')?.home != null }
        def node = h.node('1')
        def items = missionAround(node.home, 3, 25)
        assert MissionLayer.uploads(node).upload(items).get(30, TimeUnit.SECONDS).success()
        def messages = new java.util.concurrent.CopyOnWriteArrayList()

        when:
        def result = h.run('''
            v = pick { id '1'; timeout 20 }
            m = downloadMission(v)
            message "points ${m.mission().missionPoints()} first ${m.mission().getCommandList()[0].item().commandName()}"
        ''', 'download.dolphin', messages)

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('downloaded 4 mission items from vehicle 1')
        messages.contains('points 4 first NAV_TAKEOFF')
    }
}
