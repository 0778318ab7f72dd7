package dolphin.mission.transfer

import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.core.ManualClock
import dolphin.core.Position
import dolphin.mavlink.Autopilot
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import java.time.Duration
import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.mission.transfer.ScriptedMissionVehicle.ack
import static dolphin.mission.transfer.ScriptedMissionVehicle.count
import static dolphin.mission.transfer.ScriptedMissionVehicle.itemInt
import static dolphin.mission.transfer.ScriptedMissionVehicle.requestInt

/**
 * Transfers with a PX4 vehicle (AutopilotLists; docs/px4.md, "Missions"): no home item, so the
 * vehicle's seq 0 is the runtime's item 1 both ways, DO_JUMP targets with it; a download asks for one
 * item at a time, as PX4 answers only the next request or the last again; rally points in the frames
 * PX4's return reads. The spec plays the vehicle, one message at a time, on a ManualClock.
 */
@Timeout(60)
class Px4TransferSpec extends Specification {

    static final Position HOME = Position.fromDegrees(47.397742, 8.545594, 488)

    ManualClock clock = new ManualClock()
    RecordingChannel channel = new RecordingChannel(clock)
    MissionTransferConfig config = new MissionTransferConfig(dolphin.mavlink.LinkTimeouts.DEFAULT, TransferPath.ITEMS)
    MissionTransfers transfers = new MissionTransfers(channel, new ClockTimers(clock), { config })

    def setup() {
        channel.transfers = transfers
        channel.firmware = Autopilot.PX4
    }

    static List<MissionItem> mission() {
        [
                MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, HOME.atHeight(508), 0, 0, 0, Float.NaN),
                MissionItem.at(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME.displace(100, 0, 20), 0, 0, 0, Float.NaN),
                new MissionItem(3, MAV_CMD.MAV_CMD_DO_JUMP, MAV_FRAME.MAV_FRAME_MISSION, 2, 1, 0, 0, 0, 0, 0, true),
                MissionItem.at(4, MAV_CMD.MAV_CMD_NAV_LAND, HOME, 0, 0, 0, Float.NaN),
        ]
    }

    def "an upload leaves home out: MISSION_COUNT 4, the vehicle's seq 0 is item 1, the jump to item 2 goes to its seq 1"() {
        when:
        def up = transfers.upload().upload(mission())
        (0..3).each { channel.receive(requestInt(it)) }
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED))

        then:
        up.get().success()
        channel.conversation.take(3) == ['0.0 > COUNT 4', '0.0 < REQUEST_INT 0', '0.0 > ITEM 0']
        def sent = channel.sent*.message.findAll { it instanceof msg_mission_item_int }.collect { MissionItem.fromMessage(it) }
        sent*.seq == [0, 1, 2, 3]
        sent*.command == mission().drop(1)*.command
        sent[2].param1() == 1f
    }

    def "the upload's result carries the mission's id from the final ACK (opaque_id, PX4's CRC32); a download's from MISSION_COUNT"() {
        when:
        def up = transfers.upload().upload(mission())
        (0..3).each { channel.receive(requestInt(it)) }
        def accepted = ack(MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED)
        accepted.opaque_id = 0xC0FFEE01L
        channel.receive(accepted)

        then:
        up.get().planId() == 0xC0FFEE01L

        when:
        def down = transfers.download().download(MissionType.MISSION)
        def counted = count(0)
        counted.opaque_id = 0xFFFFFFFEL
        channel.receive(counted)

        then:
        down.get().success()
        down.get().planId() == 0xFFFFFFFEL
    }

    def "a lost final ACK settled by reading back takes the id from the read-back's MISSION_COUNT"() {
        when:
        def up = transfers.upload().upload(mission())
        (0..3).each { channel.receive(requestInt(it)) }
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR))
        def counted = count(4)
        counted.opaque_id = 77
        channel.receive(counted)
        mission().drop(1).collect { new MissionItem(it.seq() - 1, it.command(), it.frame(),
                (float) (it.command() == MAV_CMD.MAV_CMD_DO_JUMP ? it.param1() - 1 : it.param1()), it.param2(), it.param3(), it.param4(),
                it.x(), it.y(), it.z(), it.autocontinue()) }.each { channel.receive(itemInt(it)) }

        then:
        up.get().verified()
        up.get().planId() == 77
    }

    def "a refused item is named as the runtime numbers it"() {
        when:
        def up = transfers.upload().upload(mission())
        (0..1).each { channel.receive(requestInt(it)) }
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED))

        then:
        up.get().error().contains('item 2 (NAV_WAYPOINT)')
    }

    def "a download asks for one item at a time and gives the list with the vehicle's home as item 0, the jump's target back in the runtime's numbers"() {
        given:
        channel.home = HOME
        def held = mission().drop(1).collect { new MissionItem(it.seq() - 1, it.command(), it.frame(),
                (float) (it.command() == MAV_CMD.MAV_CMD_DO_JUMP ? it.param1() - 1 : it.param1()), it.param2(), it.param3(), it.param4(),
                it.x(), it.y(), it.z(), it.autocontinue()) }

        when:
        def down = transfers.download().download(MissionType.MISSION)
        channel.receive(count(4))

        then: 'one request outstanding, not four'
        channel.conversation.findAll { it.contains('> REQUEST_INT') } == ['0.0 > REQUEST_INT 0']

        when:
        held.each { channel.receive(itemInt(it)) }

        then:
        channel.conversation.findAll { it.contains('> REQUEST_INT') } == ['0.0 > REQUEST_INT 0', '0.0 > REQUEST_INT 1', '0.0 > REQUEST_INT 2', '0.0 > REQUEST_INT 3']
        def items = down.get().items()
        items*.seq == [0, 1, 2, 3, 4]
        items[0] == StoredItems.home(HOME)
        items.drop(1)*.command == mission().drop(1)*.command
        items[3].param1() == 2f
        MissionVerification.firstDifference(Autopilot.PX4, MissionType.MISSION, mission(), items).empty
    }

    def "a lost final ACK is settled by reading the mission back, compared by what PX4 keeps: the landing's abort height comes back 0"() {
        given:
        def land = mission()[4]
        def sent = mission().take(4) + [new MissionItem(4, land.command(), land.frame(), 5, 0, 0, 0, land.x(), land.y(), land.z(), true)]
        def held = sent.drop(1).collect { new MissionItem(it.seq() - 1, it.command(), it.frame(),
                (float) (it.command() == MAV_CMD.MAV_CMD_DO_JUMP ? it.param1() - 1 : it.command() == MAV_CMD.MAV_CMD_NAV_LAND ? 0 : it.param1()),
                it.param2(), it.param3(), it.param4(), it.x(), it.y(), it.z(), it.autocontinue()) }

        when: 'every item taken, then ERROR for the last one repeated: the final ACK was lost'
        def up = transfers.upload().upload(sent)
        (0..3).each { channel.receive(requestInt(it)) }
        channel.receive(ack(MAV_MISSION_RESULT.MAV_MISSION_ERROR))
        channel.receive(count(4))
        held.each { channel.receive(itemInt(it)) }

        then:
        up.get().success()
        up.get().verified()
    }

    def "an unanswered request goes again alone"() {
        when:
        def down = transfers.download().download(MissionType.MISSION)
        channel.receive(count(2))
        clock.advance(Duration.ofSeconds(2))

        then:
        channel.conversation.findAll { it.contains('> REQUEST_INT') }.every { it.endsWith('REQUEST_INT 0') }
        channel.conversation.count { it.contains('> REQUEST_INT') } > 1
        !down.done
    }

    def "PX4 gives back 0 for the param1 of a command with a position it does not keep; verification knows which it keeps"() {
        given:
        def sent = mission()
        def takeOff = sent[1]
        def back = sent.collect { it }
        back[1] = new MissionItem(1, takeOff.command(), takeOff.frame(), 0, 0, 0, 0, takeOff.x(), takeOff.y(), takeOff.z(), true)
        def waypoint = sent[2]
        def held = new MissionItem(2, waypoint.command(), waypoint.frame(), 5, 0, 0, 0, waypoint.x(), waypoint.y(), waypoint.z(), true)
        sent[1] = new MissionItem(1, takeOff.command(), takeOff.frame(), 15, 0, 0, 0, takeOff.x(), takeOff.y(), takeOff.z(), true)

        expect:
        MissionVerification.firstDifference(Autopilot.PX4, MissionType.MISSION, sent, back).empty
        MissionVerification.firstDifference(Autopilot.ARDUPILOT, MissionType.MISSION, sent, back).present
        MissionVerification.firstDifference(Autopilot.PX4, MissionType.MISSION, sent, back.take(2) + [held] + back.drop(3)).get() ==
                'item 2 (NAV_WAYPOINT): param1 sent 0.0, vehicle has 5.0'
    }

    def "rally points go to PX4 in GLOBAL or GLOBAL_RELATIVE_ALT; ArduPilot's as written"() {
        given:
        def rally = [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_RALLY_POINT, HOME.atHeight(518), 0, 0, 0, 0)]

        expect:
        rally[0].frame() == MAV_FRAME.MAV_FRAME_GLOBAL_INT
        AutopilotLists.toVehicle(Autopilot.PX4, MissionType.RALLY, rally)*.frame() == [MAV_FRAME.MAV_FRAME_GLOBAL]
        AutopilotLists.toVehicle(Autopilot.ARDUPILOT, MissionType.RALLY, rally) == rally
        AutopilotLists.toVehicle(Autopilot.PX4, MissionType.FENCE, rally) == rally
        AutopilotLists.toVehicle(Autopilot.ARDUPILOT, MissionType.MISSION, mission()) == mission()
    }
}
