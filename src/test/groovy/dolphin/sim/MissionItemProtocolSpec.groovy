package dolphin.sim

import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_request
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import spock.lang.Specification

import static dolphin.sim.MissionProtocolSpec.plan

/**
 * The upload side of the mission protocol on a fake clock, no sockets: its timing and its answers to
 * items ArduPilot does not expect (MissionItemProtocol.cpp, GCS_MAVLINK::handle_mission_item).
 */
class MissionItemProtocolSpec extends Specification {

    SimDriver d = new SimDriver(VehicleKind.COPTER)

    def "without items the request is repeated once more than 1 s passed, and the upload cancelled once more than 8 s passed; COUNT has already truncated"() {
        given: 'a stored mission of six items'
        assert d.upload(plan()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.run(1)
        long start = d.now
        int from = d.mark()

        when:
        d.handle(new msg_mission_count(target_system: 1, target_component: 1, count: 3))
        def truncated = d.vehicle.mission().size()
        d.runUntil(10, 'the cancel') { !d.vehicle.missionUploading() }

        then: 'requests at 0 s, then every 1.05 s (the first 50 ms tick past a second)'
        truncated == 3
        def requests = d.sent.drop(from).findAll { it.message instanceof msg_mission_request }
        requests*.message*.seq.every { it == 0 }
        requests*.at.collect { (it - start) / 1_000_000 as long } == [0, 1050, 2100, 3150, 4200, 5250, 6300, 7350]

        and: 'the cancel at 8.05 s, with the text'
        def ack = d.sent.drop(from).find { it.message instanceof msg_mission_ack }
        ack.message.type == MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED
        (ack.at - start) / 1_000_000 as long == 8050
        d.texts(from) == ['Mission upload timeout']
        d.vehicle.mission().size() == 3
    }

    def "an item keeps the upload alive: the 8 s count from the last item accepted, not from COUNT"() {
        given:
        long start = d.now
        d.handle(new msg_mission_count(target_system: 1, target_component: 1, count: 3))
        d.run(5)
        d.handle(plan()[0].toMessage(1, 1))
        int from = d.mark()

        when:
        d.runUntil(10, 'the cancel') { !d.vehicle.missionUploading() }

        then:
        def ack = d.sent.drop(from).find { it.message instanceof msg_mission_ack }
        ack.message.type == MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED
        (ack.at - start) / 1_000_000 as long == 13050
    }

    def "an item when no upload is in progress, as the last one repeated after its ACK was lost, is answered MAV_MISSION_ERROR and changes nothing"() {
        given:
        def items = plan()
        assert d.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        def stored = d.vehicle.mission()
        int from = d.mark()

        when:
        d.handle(items.last().toMessage(1, 1))

        then:
        d.since(from, msg_mission_ack)*.type == [MAV_MISSION_RESULT.MAV_MISSION_ERROR]
        d.since(from, msg_mission_request).isEmpty()
        d.vehicle.mission() == stored
    }

    def "during an upload the seq is checked before the sender: another sender's wrong seq is INVALID_SEQUENCE, its right one DENIED"() {
        given:
        def items = plan()
        d.handle(new msg_mission_count(target_system: 1, target_component: 1, count: items.size()))
        int from = d.mark()

        when:
        d.handle(items[1].toMessage(1, 1), 254, 190)
        d.handle(items[0].toMessage(1, 1), 254, 190)

        then:
        d.since(from, msg_mission_ack)*.type == [MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE, MAV_MISSION_RESULT.MAV_MISSION_DENIED]
        d.vehicle.missionUploading()
    }

    static MissionItem rallyPoint(int seq, double north) {
        def p = SimDriver.HOME.displace(north, 0, 0)
        new MissionItem(seq, MAV_CMD.MAV_CMD_NAV_RALLY_POINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0, 0,
                MissionItem.degE7(p.latitudeDegrees()), MissionItem.degE7(p.longitudeDegrees()), 30, false)
    }

    def "rally points are stored as they arrive: a refused one leaves the new ones before it and the old ones after, as MissionItemProtocol_Rally"() {
        given:
        def old = (0..3).collect { rallyPoint(it, 100 + it) }
        assert d.upload(old, MissionType.RALLY) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        def fresh = [rallyPoint(0, 500), rallyPoint(1, 501), MissionItem.command(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0, 0, 0, 0)]

        when:
        int result = d.upload(fresh, MissionType.RALLY)

        then:
        result == MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        d.vehicle.rallyPoints().items() == [fresh[0], fresh[1], old[2]]
    }

    def "a DO_JUMP to #target in a mission of 6 is #expected"() {
        given:
        def items = plan()
        items[2] = MissionItem.command(2, MAV_CMD.MAV_CMD_DO_JUMP, target, 1, 0, 0)

        expect:
        d.upload(items) == expected
        !d.vehicle.missionUploading()

        where:
        target || expected
        0      || MAV_MISSION_RESULT.MAV_MISSION_ERROR
        1      || MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        5      || MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        6      || MAV_MISSION_RESULT.MAV_MISSION_ERROR
    }
}
