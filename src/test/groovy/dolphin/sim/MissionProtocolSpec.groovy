package dolphin.sim

import com.MAVLink.common.msg_file_transfer_protocol
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_clear_all
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.common.msg_mission_request
import com.MAVLink.common.msg_mission_request_int
import com.MAVLink.common.msg_mission_request_list
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_MODE_FLAG
import com.MAVLink.enums.MAV_RESULT
import dolphin.core.Position
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import dolphin.mission.transfer.MissionFtpFile
import spock.lang.AutoCleanup
import dolphin.mission.transfer.StoredItems
import spock.lang.Specification

/** The vehicle side of the mission protocol, against a bare ground station (ardupilot-behaviour.md §2.4). */
class MissionProtocolSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    @AutoCleanup
    RawGroundStation gcs = new RawGroundStation()

    static MissionItem rel(int seq, int command, double north, double east, double up, float p1 = 0, float p2 = 0) {
        def p = HOME.displace(north, east, 0)
        new MissionItem(seq, command, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, p1, p2, 0, 0,
                MissionItem.degE7(p.latitudeDegrees()), MissionItem.degE7(p.longitudeDegrees()), (float) up, true)
    }

    static List<MissionItem> plan() {
        [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME.displace(5, 5, -20), 0, 0, 0, 0),
         rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10),
         MissionItem.command(2, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 1, 5, -1, 0),
         rel(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 0, 10),
         MissionItem.command(4, MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, 0, 2, 0, 0),
         MissionItem.at(5, MAV_CMD.MAV_CMD_NAV_LAND, HOME.displace(30, 0, 0), 0, 0, 0, 0)]
    }

    def "an upload is asked for with MISSION_REQUEST, ends ACCEPTED with 'Flight plan received', and seq 0 becomes home"() {
        given:
        def items = plan()
        int from = gcs.mark()

        when:
        int result = gcs.upload(items)

        then:
        result == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        gcs.since(from, msg_mission_request)*.seq.toUnique() == (0..5).toList() // re-requested once a second (50 ms here)
        gcs.since(from, msg_mission_request_int).isEmpty()
        gcs.await(from, msg_statustext) { it.text == 'Flight plan received' }

        and: 'what is stored equals the upload, except seq 0: home, AMSL, frame GLOBAL; downloads report items as ArduPilot keeps them'
        def stored = gcs.vehicle().mission()
        stored.drop(1) == items.drop(1)
        def down = gcs.download()
        down.drop(1) == stored.drop(1).collect { StoredItems.missionItem(it, false) }
        down[0] == stored[0]
        with(down[0]) {
            seq() == 0
            command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT
            frame() == MAV_FRAME.MAV_FRAME_GLOBAL
            x() == MissionItem.degE7(HOME.latitudeDegrees())
            y() == MissionItem.degE7(HOME.longitudeDegrees())
            Math.abs(z() - 820) < 0.01
        }
    }

    def "a wrong seq is answered INVALID_SEQUENCE and the upload still completes"() {
        given:
        def items = plan().take(3)
        int from = gcs.mark()

        when: 'the first request is answered with item 1'
        gcs.send(new msg_mission_count(target_system: 1, target_component: 1, count: 3))
        gcs.await(from, msg_mission_request) { it.seq == 0 }
        gcs.send(items[1].toMessage(1, 1))

        then:
        gcs.await(from, msg_mission_ack).type == MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE

        when: 'the right items follow'
        int next = gcs.mark()
        gcs.send(items[0].toMessage(1, 1))
        gcs.await(next, msg_mission_request) { it.seq == 1 }
        gcs.send(items[1].toMessage(1, 1))
        gcs.await(next, msg_mission_request) { it.seq == 2 }
        gcs.send(items[2].toMessage(1, 1))

        then:
        gcs.await(next, msg_mission_ack).type == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        gcs.vehicle().mission().drop(1) == items.drop(1)
    }

    def "during an upload another sender is DENIED, and so is a download; the same sender may restart"() {
        given:
        def items = plan().take(3)
        int from = gcs.mark()
        gcs.send(new msg_mission_count(target_system: 1, target_component: 1, count: 3))
        gcs.await(from, msg_mission_request) { it.seq == 0 }

        when: 'another ground station sends a COUNT and an item'
        int other = gcs.mark()
        gcs.send(new msg_mission_count(target_system: 1, target_component: 1, count: 2), 254, 190)
        gcs.send(items[0].toMessage(1, 1), 254, 190)

        then:
        gcs.await(other, msg_mission_ack, 5) { it.target_system == 254 }.type == MAV_MISSION_RESULT.MAV_MISSION_DENIED
        gcs.waitFor(5, 'two DENIED acks') { gcs.since(other, msg_mission_ack).count { it.target_system == 254 } == 2 }
        gcs.since(other, msg_mission_ack).every { it.type == MAV_MISSION_RESULT.MAV_MISSION_DENIED }

        when: 'the uploader itself asks for a download'
        int down = gcs.mark()
        gcs.send(new msg_mission_request_list(target_system: 1, target_component: 1))
        gcs.send(new msg_mission_request_int(target_system: 1, target_component: 1, seq: 0))

        then:
        gcs.waitFor(5, 'two acks') { gcs.since(down, msg_mission_ack).size() == 2 }
        gcs.since(down, msg_mission_ack)*.type == [MAV_MISSION_RESULT.MAV_MISSION_DENIED] * 2
        gcs.since(down, msg_mission_count).isEmpty()
        gcs.vehicle().missionUploading()

        when: 'the first sender restarts with a new COUNT and finishes'
        int result = gcs.upload(items)

        then:
        result == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        gcs.vehicle().mission().size() == 3
    }

    def "an unanswered upload is cancelled over the link: OPERATION_CANCELLED and the text reach the sender (timing: MissionItemProtocolSpec)"() {
        given:
        int from = gcs.mark()

        when:
        gcs.send(new msg_mission_count(target_system: 1, target_component: 1, count: 3))
        def ack = gcs.await(from, msg_mission_ack, 10)

        then:
        ack.type == MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED
        ack.target_system == 255
        gcs.since(from, msg_mission_request).every { it.seq == 0 }
        gcs.await(from, msg_statustext) { it.text == 'Mission upload timeout' }
        !gcs.vehicle().missionUploading()
    }

    def "a mission written over MAVLink FTP by a bare client is stored, with no item protocol on the link"() {
        given:
        def items = plan()
        byte[] file = MissionFtpFile.encode(MissionType.MISSION, items)
        int from = gcs.mark()

        when: 'CreateFile, one WriteFile (the whole file is 238 bytes), TerminateSession'
        def replies = [[0, SimFtpPacket.CREATE_FILE, [data: MissionFtpFile.path(MissionType.MISSION)]],
                       [2, SimFtpPacket.WRITE_FILE, [data: file]],
                       [4, SimFtpPacket.TERMINATE_SESSION, [:]]].collect { int seq, int opcode, Map fields ->
            int mark = gcs.mark()
            gcs.send(SimFtpServerSpec.ftpRequest(seq, opcode, fields))
            SimFtpPacket.of(gcs.await(mark, msg_file_transfer_protocol) { SimFtpPacket.of(it).seq() == seq + 1 })
        }

        then:
        replies*.opcode() == [SimFtpPacket.ACK] * 3
        gcs.vehicle().mission().drop(1) == items.drop(1)
        gcs.since(from, msg_mission_request).isEmpty()
    }

    def "item checks: #what is answered #expected and ends the upload"() {
        given:
        def items = [plan()[0], item]
        int from = gcs.mark()

        when:
        int result = gcs.upload(items)

        then:
        result == expected
        !gcs.vehicle().missionUploading()
        gcs.since(from, msg_mission_request)*.seq.toUnique() == [0, 1]

        where:
        what                      | item                                                                                  || expected
        'DO_CHANGE_ALTITUDE'      | MissionItem.command(1, MAV_CMD.MAV_CMD_DO_CHANGE_ALTITUDE, 30, 0, 0, 0)               || MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        'DO_TRIGGER_CONTROL'      | MissionItem.command(1, MAV_CMD.MAV_CMD_DO_TRIGGER_CONTROL, 1, 0, 0, 0)                || MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        'a waypoint in LOCAL_NED' | new MissionItem(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_LOCAL_NED, 0, 0, 0, 0, 10, 10, -5, true) || MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED_FRAME
        'a NaN altitude'          | rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 10, 0, Double.NaN)                                || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM7
        'latitude 95°'            | new MissionItem(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 0, 0, 0, 0, 950_000_000, 0, 10, true) || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM5_X
        'longitude 190°'          | new MissionItem(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 0, 0, 0, 0, 0, 1_900_000_000, 10, true) || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM6_Y
        'IMAGE_START_CAPTURE'     | MissionItem.command(1, MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, 0, 2, 0, 0)               || MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        'a NaN delay'             | MissionItem.command(1, MAV_CMD.MAV_CMD_CONDITION_DELAY, Float.NaN, 0, 0, 0)           || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1
        'a NaN in a speed change' | MissionItem.command(1, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 1, 5, -1, Float.NaN)          || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM4
        'a NaN in an unknown command, checked first' | MissionItem.command(1, MAV_CMD.MAV_CMD_DO_CHANGE_ALTITUDE, 30, Float.NaN, 0, 0) || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM2
        'a waypoint with a NaN yaw' | new MissionItem(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0, Float.NaN, 404442330, -73752340, 10, true) || MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        'a waypoint with a NaN pass radius' | new MissionItem(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, Float.NaN, 0, 404442330, -73752340, 10, true) || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM3
        'an infinite hold time'   | rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 10, 0, 10, Float.POSITIVE_INFINITY)              || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1
        'a hold time of 70000 s'  | rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 10, 0, 10, 70_000)                               || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1
        'a negative hold time'    | rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 10, 0, 10, -1)                                   || MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1
        'a hold time of 65535 s'  | rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 10, 0, 10, 65_535)                               || MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
    }

    def "ArduPlane ignores a waypoint's hold time (param1): 70000 is accepted, a NaN is not; it refuses spline waypoints"() {
        given:
        def plane = new RawGroundStation(VehicleKind.PLANE)

        expect:
        plane.upload([plan()[0], rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 10, 0, 10, 70_000)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        plane.upload([plan()[0], rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 10, 0, 10, Float.NaN)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1
        plane.upload([plan()[0], rel(1, MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, 10, 0, 10)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED

        cleanup:
        plane?.close()
    }

    def "a COUNT above the capacity is NO_SPACE"() {
        given:
        def small = new RawGroundStation(VehicleKind.COPTER, 20, SimOptions.DEFAULT.withMissionCapacity(4))
        int from = small.mark()

        when:
        small.send(new msg_mission_count(target_system: 1, target_component: 1, count: 5))

        then:
        small.await(from, msg_mission_ack).type == MAV_MISSION_RESULT.MAV_MISSION_NO_SPACE
        !small.vehicle().missionUploading()

        cleanup:
        small?.close()
    }

    def "MISSION_CLEAR_ALL is refused with ERROR while flying AUTO, and accepted on the ground"() {
        given: 'a mission of a takeoff and an unlimited loiter'
        def items = [plan()[0], rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10), rel(2, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, 20, 0, 10)]
        assert gcs.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED

        when: 'flying it'
        assert gcs.command(MAV_CMD.MAV_CMD_DO_SET_MODE, [MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, COPTER_MODE.COPTER_MODE_GUIDED]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert gcs.command(MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, [1]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert gcs.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        gcs.waitFor(10, 'climbing') { gcs.vehicle().position().hae() > 823 }
        int from = gcs.mark()
        gcs.send(new msg_mission_clear_all(target_system: 1, target_component: 1))

        then:
        gcs.await(from, msg_mission_ack).type == MAV_MISSION_RESULT.MAV_MISSION_ERROR
        gcs.vehicle().mission().size() == 3

        when: 'on the ground, disarmed'
        def ground = new RawGroundStation()
        assert ground.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        int f2 = ground.mark()
        ground.send(new msg_mission_clear_all(target_system: 1, target_component: 1))

        then:
        ground.await(f2, msg_mission_ack).type == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        ground.vehicle().mission().size() == 1

        cleanup:
        ground?.close()
    }
}
