package dolphin.sim

import com.MAVLink.common.msg_extended_sys_state
import com.MAVLink.common.msg_file_transfer_protocol
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_mission_request_int
import com.MAVLink.common.msg_mission_request_list
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_request
import com.MAVLink.common.msg_mission_set_current
import com.MAVLink.common.msg_set_mode
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_MODE_FLAG
import com.MAVLink.enums.MAV_PROTOCOL_CAPABILITY
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.enums.MAV_VTOL_STATE
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.minimal.msg_heartbeat
import com.MAVLink.standard.msg_autopilot_version
import dolphin.mavlink.Autopilot
import dolphin.mavlink.Px4Modes
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import spock.lang.Specification

import static dolphin.sim.MissionProtocolSpec.rel
import static dolphin.sim.SimDriver.HOME
import static dolphin.sim.SimFtpPacket.*

/**
 * Simulated PX4 vehicles (--sim-autopilot px4) on a fake clock, no sockets: what PX4's SITL did
 * (docs/mavlink.md, "Simulated PX4 vehicles"), with the vehicle's own numbering, the first item seq 0.
 */
class Px4SimVehicleSpec extends Specification {

    static final SimOptions PX4 = SimOptions.DEFAULT.withAutopilot(Autopilot.PX4)
    static final long LOITER = Px4Modes.customMode(Px4Modes.MAIN_AUTO, Px4Modes.AUTO_LOITER)
    static final long MISSION = Px4Modes.customMode(Px4Modes.MAIN_AUTO, Px4Modes.AUTO_MISSION)
    static final long RTL = Px4Modes.customMode(Px4Modes.MAIN_AUTO, Px4Modes.AUTO_RTL)

    static SimDriver px4(VehicleKind kind = VehicleKind.COPTER) {
        def d = new SimDriver(kind, PX4)
        d.handle(new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_GCS, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_INVALID))
        d
    }

    /** TAKEOFF to 10 m, a DO item, a waypoint 40 m north, LAND there: the first item is seq 0. */
    static List<MissionItem> survey() {
        [rel(0, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10, 15),
         MissionItem.command(1, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 1, 5, -1, 0),
         new MissionItem(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 2, 5, 0,
                 rel(0, 0, 40, 0, 0).x(), rel(0, 0, 40, 0, 0).y(), 10, true),
         rel(3, MAV_CMD.MAV_CMD_NAV_LAND, 40, 0, 0, 7)]
    }

    static def setMode(SimDriver d, Number p2, Number p3 = 0) {
        d.command(MAV_CMD.MAV_CMD_DO_SET_MODE, [MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, p2, p3])
    }

    /** The values in order, each run of equal ones as one. */
    static List runs(List values) {
        values.inject([]) { List l, v -> l && l.last() == v ? l : l + [v] }
    }

    static def current(SimDriver d) {
        d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT])
        d.since(0, msg_mission_current).last()
    }

    def "a PX4 copter's heartbeat: autopilot PX4, a quadrotor booting in AUTO.LOITER; a VTOL is VTOL_RESERVED2, MC on the ground"() {
        when:
        def copter = px4()
        copter.run(1.5)
        def vtol = px4(VehicleKind.QUADPLANE)
        vtol.run(1.5)

        then:
        with(copter.since(0, msg_heartbeat).last()) {
            autopilot == MAV_AUTOPILOT.MAV_AUTOPILOT_PX4
            type == MAV_TYPE.MAV_TYPE_QUADROTOR
            custom_mode == LOITER
        }
        copter.vehicle.modeName() == 'AUTO.LOITER'
        vtol.since(0, msg_heartbeat).last().type == MAV_TYPE.MAV_TYPE_VTOL_RESERVED2
        vtol.since(0, msg_extended_sys_state).last().vtol_state == MAV_VTOL_STATE.MAV_VTOL_STATE_MC
    }

    def "STATUSTEXT goes out only once a ground station's heartbeat was heard; what was said before is lost"() {
        given:
        def d = new SimDriver(VehicleKind.COPTER, PX4)

        when: 'armed and disarmed before any ground station heartbeat'
        d.arm()
        d.command(MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, [0])

        then:
        d.texts().empty

        when:
        d.handle(new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_GCS))
        d.arm()

        then:
        d.texts() == ['Armed by external command']
    }

    def "DO_SET_MODE takes the main mode in param2 and the sub mode in param3; a whole custom_mode in param2 is ACCEPTED and changes nothing"() {
        given:
        def d = px4()

        expect: 'the whole AUTO.MISSION value in param2, as ArduPilot takes it'
        setMode(d, MISSION).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.mode() == LOITER

        and: 'main 4, sub 4'
        setMode(d, Px4Modes.MAIN_AUTO, Px4Modes.AUTO_MISSION).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.modeName() == 'AUTO.MISSION'

        and: 'AUTO with sub mode 0 is AUTO.MISSION; a sub mode PX4 does not have is TEMPORARILY_REJECTED'
        setMode(d, Px4Modes.MAIN_POSCTL).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.modeName() == 'POSCTL'
        setMode(d, Px4Modes.MAIN_AUTO, 0).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.modeName() == 'AUTO.MISSION'
        setMode(d, Px4Modes.MAIN_AUTO, 7).result == MAV_RESULT.MAV_RESULT_TEMPORARILY_REJECTED
        d.vehicle.modeName() == 'AUTO.MISSION'

        when: 'SET_MODE carries the whole custom_mode'
        d.handle(new msg_set_mode(target_system: 1, base_mode: MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, custom_mode: RTL))

        then:
        d.vehicle.modeName() == 'AUTO.RTL'
    }

    def "a mission has no home item: MISSION_COUNT counts the real items, seq 0 is the first both ways, and a download gives back what PX4 keeps"() {
        given:
        def d = px4()

        expect: 'no mission: total 65535, NO_MISSION'
        with(current(d)) { total == 65535 && mission_state == MISSION_STATE.MISSION_STATE_NO_MISSION }

        when:
        int result = d.upload(survey())

        then: 'stored home first, as every simulated vehicle keeps it; on the wire 4 items, NOT_STARTED at seq 0'
        result == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.vehicle.mission().size() == 5
        d.vehicle.mission()[1].command() == MAV_CMD.MAV_CMD_NAV_TAKEOFF
        with(current(d)) { seq == 0 && total == 4 && mission_state == MISSION_STATE.MISSION_STATE_NOT_STARTED }
        !d.texts().contains('Flight plan received')

        when: 'downloaded'
        int from = d.mark()
        d.handle(new msg_mission_request_list(target_system: 1, target_component: 1))
        int count = d.since(from, msg_mission_count).last().count
        (0..<count).each { d.handle(new msg_mission_request_int(target_system: 1, target_component: 1, seq: it)) }
        def down = d.since(from, msg_mission_item_int)

        then: "seq 0 is the take-off; its pitch (p1), the waypoint's pass radius (p3) and the landing's abort altitude (p1) come back 0"
        count == 4
        down*.seq == [0, 1, 2, 3]
        down*.command == [MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LAND]
        down[0].param1 == 0
        down[1].param2 == 5
        down[2].param2 == 2 && down[2].param3 == 0
        down[3].param1 == 0
    }

    def "an upload refuses what PX4 refuses: a DO item in a global frame, LOITER_TURNS, SPLINE_WAYPOINT, CONDITION_YAW, DO_SET_SERVO, a local frame"() {
        given:
        def d = px4()

        expect:
        d.upload([item]) == result

        where:
        item                                                                                                      | result
        new MissionItem(0, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT, 1, 5, -1, 0, 0, 0, 0, true) | MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        new MissionItem(0, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, MAV_FRAME.MAV_FRAME_GLOBAL, 0, 0, 0, 0, 0, 0, 0, true) | MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        rel(0, MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, 10, 0, 10, 2)                                                   | MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        rel(0, MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, 10, 0, 10)                                                   | MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        MissionItem.command(0, MAV_CMD.MAV_CMD_CONDITION_YAW, 90, 0, 1, 0)                                        | MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        MissionItem.command(0, MAV_CMD.MAV_CMD_DO_SET_SERVO, 5, 1500, 0, 0)                                       | MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
        new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_LOCAL_NED, 0, 0, 0, 0, 10, 0, -10, true) | MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED_FRAME
        rel(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 10, 0, 10)                                                          | MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        MissionItem.command(0, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, 0, 0, 0, 0)                                  | MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
    }

    def "PX4's side of the protocol: a wrong seq is ignored, the last item again after the end ACCEPTED, an upload left 5 s cancelled"() {
        given:
        def d = px4()
        def items = [rel(0, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10), rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 0, 10)]

        when: 'item 1 before item 0 was asked for'
        d.handle(new msg_mission_count(target_system: 1, target_component: 1, count: 2))
        int from = d.mark()
        d.handle(items[1].toMessage(1, 1, MissionType.MISSION))

        then: 'no answer'
        d.sent.size() == from

        when: 'the upload completes and its last item comes again, as after a lost ACK'
        d.upload(items)
        from = d.mark()
        d.handle(items[1].toMessage(1, 1, MissionType.MISSION))

        then:
        d.since(from, msg_mission_ack)*.type == [MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED]

        when: 'another upload is left after its first item'
        d.handle(new msg_mission_count(target_system: 1, target_component: 1, count: 2))
        d.handle(items[0].toMessage(1, 1, MissionType.MISSION))
        from = d.mark()
        d.run(5.1)

        then: "item 1 asked for again once more than 250 ms passed (300 ms on the fleet's 50 ms ticks), then the upload cancelled"
        d.since(from, msg_mission_request).size() == 16
        d.since(from, msg_mission_ack)*.type == [MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED]
        d.texts(from) == ['Operation timeout']
    }

    def "MISSION_START without a valid mission is DENIED, saying so; with one it arms, enters AUTO.MISSION and flies from seq 0"() {
        given:
        def d = px4()

        expect:
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0]).result == MAV_RESULT.MAV_RESULT_DENIED
        d.texts().last() == 'Mission start denied! No valid mission'
        !d.vehicle.armed()

        when:
        d.upload(survey())
        int from = d.mark()
        def ack = d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])

        then:
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.armed()
        d.vehicle.modeName() == 'AUTO.MISSION'
        d.texts(from) == ['Armed by mission start']

        when: 'it takes off'
        d.runUntil(30, 'the take-off reached') { !d.since(from, msg_mission_item_reached).empty }

        then: "the take-off, seq 0, done with the DO item after it: only the latest is sent, seq 1; MISSION_CURRENT ACTIVE in PX4's numbering"
        d.since(from, msg_mission_item_reached)[0].seq == 1
        with(current(d)) { mission_state == MISSION_STATE.MISSION_STATE_ACTIVE && total == 4 && mission_mode == 1 }
    }

    def "MISSION_ITEM_REACHED goes out on a change and then 10 more times a second apart, only the latest seq"() {
        given:
        def d = px4()
        d.upload([rel(0, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10), rel(1, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, 0, 0, 10)])
        int from = d.mark()
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])

        when:
        d.runUntil(30, 'the take-off reached') { !d.since(from, msg_mission_item_reached).empty }
        long first = d.sent[d.indexOf(from) { it instanceof msg_mission_item_reached }].at
        d.run(15)
        def reached = d.sent.drop(from).findAll { it.message instanceof msg_mission_item_reached }

        then:
        reached.size() == 11
        reached.every { it.message.seq == 0 }
        reached.collect { Math.round((it.at - first) / 1e9) } == (0..10).toList()
    }

    def "a mission's landing is reached as its descent begins; landed, the mission ends and disarms it at once, still in AUTO.MISSION, COMPLETE"() {
        given:
        def d = px4()
        d.upload(survey())
        int from = d.mark()
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])

        when:
        d.runUntil(180, 'the disarm') { !d.vehicle.armed() }
        int landReached = d.indexOf(from) { it instanceof msg_mission_item_reached && it.seq == 3 }
        int detected = d.indexOf(from) { it instanceof msg_statustext && it.text == 'Landing detected' }

        then: 'reached over the landing point, 10 m up: its descent takes more than 10 s'
        landReached >= 0 && (d.sent[detected].at - d.sent[landReached].at) / 1e9 > 10

        and: 'as px4-copter-fenced-hop: the texts in this order, in one step'
        d.texts(detected) == ['Landing detected', 'Mission finished, landed', 'Disarmed by landing']
        d.sent.drop(detected).findAll { it.message instanceof msg_statustext }*.at.unique().size() == 1
        d.vehicle.modeName() == 'AUTO.MISSION'
        d.vehicle.position().horizontalDistanceTo(HOME.displace(40, 0, 0)) < 2
        with(current(d)) { mission_state == MISSION_STATE.MISSION_STATE_COMPLETE && seq == 3 }
    }

    def "a mission has an id (MISSION_ACK, MISSION_COUNT, MISSION_CURRENT); the same mission again is not taken again, COMPLETE stays and MISSION_START flies it again"() {
        given: 'the survey flown to the end'
        def d = px4()
        int from = d.mark()
        d.upload(survey())
        long id = d.since(from, msg_mission_ack).last().opaque_id
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])
        d.runUntil(180, 'the disarm') { !d.vehicle.armed() }

        when: 'the same survey again'
        from = d.mark()
        d.upload(survey())

        then:
        id != 0
        d.since(from, msg_mission_ack).last().opaque_id == id
        with(current(d)) { mission_state == MISSION_STATE.MISSION_STATE_COMPLETE && mission_id == id && seq == 3 }

        when:
        d.handle(new msg_mission_request_list(target_system: 1, target_component: 1))

        then:
        d.since(from, msg_mission_count).last().opaque_id == id

        when:
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])
        d.runUntil(60, 'the take-off again') { d.vehicle.position().hae() > HOME.hae() + 5 }

        then:
        d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE

        when: 'another mission, landed'
        d.runUntil(180, 'the disarm') { !d.vehicle.armed() }
        from = d.mark()
        d.upload(survey().take(3) + [rel(3, MAV_CMD.MAV_CMD_NAV_LAND, 30, 0, 0, 7)])
        long other = d.since(from, msg_mission_ack).last().opaque_id

        then:
        other != 0 && other != id
        with(current(d)) { mission_state == MISSION_STATE.MISSION_STATE_NOT_STARTED && mission_id == other && seq == 0 }
    }

    def "REQUEST_MESSAGE of a message it does not send is DENIED, as its SITL denied a camera's and a gimbal's information; what it sends is ACCEPTED"() {
        given:
        def d = px4()

        expect:
        d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [259]).result == MAV_RESULT.MAV_RESULT_DENIED
        d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [280]).result == MAV_RESULT.MAV_RESULT_DENIED
        d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [msg_autopilot_version.MAVLINK_MSG_ID_AUTOPILOT_VERSION]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
    }

    def "PX4's descent: MPC_Z_VEL_MAX_DN above MPC_LAND_ALT1, MPC_LAND_SPEED below MPC_LAND_ALT2, in proportion between"() {
        expect:
        Math.abs(Px4Landing.sinkRate(height) - rate) < 1e-9

        where:
        height || rate
        30     || 1.5
        10     || 1.5
        7.5    || 1.1
        5      || 0.7
        1      || 0.7
    }

    def "a mission that does not end with a landing holds at its last item, armed in AUTO.MISSION, COMPLETE"() {
        given:
        def d = px4()
        d.upload([rel(0, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10), rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 0, 10)])
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])

        when:
        d.runUntil(60, 'the mission complete') { d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE }
        d.run(20)

        then:
        d.texts().last() == 'Mission finished, loitering'
        d.vehicle.armed()
        d.vehicle.modeName() == 'AUTO.MISSION'
        d.vehicle.position().distanceTo(HOME.displace(30, 0, -10)) < 2
    }

    def "a multicopter needs no take-off item: MISSION_START flies a mission of waypoints from the ground"() {
        given:
        def d = px4()
        d.upload([rel(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 0, 15)])

        when:
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])
        d.runUntil(60, 'the waypoint reached') { !d.since(0, msg_mission_item_reached).empty }

        then:
        d.vehicle.position().distanceTo(HOME.displace(30, 0, -15)) < 2
    }

    def "armed on the ground without a mission to fly, a multicopter disarms itself after 10 s (COM_DISARM_PRFLT); a plane does not"() {
        given:
        def copter = px4()
        def plane = px4(VehicleKind.PLANE)

        when:
        copter.arm()
        plane.arm()
        copter.run(9.9)

        then:
        copter.vehicle.armed()

        when:
        copter.run(0.2)
        plane.run(30)

        then:
        !copter.vehicle.armed()
        copter.texts().last() == 'Disarmed by auto preflight disarming'
        plane.vehicle.armed()
    }

    def "AUTO.RTL climbs to 60 m above home, returns, lands and disarms"() {
        given:
        def d = px4()
        d.upload([rel(0, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 20), rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 50, 0, 20),
                  rel(2, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, 50, 0, 20)])
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])
        d.runUntil(60, 'the loiter') { d.vehicle.missionCurrent() == 3 }

        when:
        setMode(d, Px4Modes.MAIN_AUTO, Px4Modes.AUTO_RTL)
        double highest = 0
        d.runUntil(200, 'the disarm') {
            highest = Math.max(highest, d.vehicle.position().hae() - HOME.hae())
            !d.vehicle.armed()
        }

        then:
        Math.abs(highest - Px4Firmware.RTL_RETURN_ALT) < 0.5
        d.vehicle.position().distanceTo(HOME) < 2
        d.texts().last() == 'Disarmed by landing'
    }

    def "a fixed wing's mission without a landing is no valid mission (MIS_TKO_LAND_REQ 2): NO_MISSION with its total, and MISSION_START DENIED"() {
        given:
        def d = px4(VehicleKind.PLANE)

        when:
        int result = d.upload([rel(0, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 30),
                               rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 500, 0, 30),
                               MissionItem.command(2, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, 0, 0, 0, 0)])

        then:
        result == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        with(current(d)) { mission_state == MISSION_STATE.MISSION_STATE_NO_MISSION && total == 3 } // its items, as px4-copter-fence-refused's
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0]).result == MAV_RESULT.MAV_RESULT_DENIED
        d.texts().last() == 'Mission start denied! No valid mission'

        when: 'the same with a landing'
        d.upload([rel(0, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 30), rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 500, 0, 30),
                  rel(2, MAV_CMD.MAV_CMD_NAV_LAND, 1200, 0, 0)])

        then:
        current(d).mission_state == MISSION_STATE.MISSION_STATE_NOT_STARTED
    }

    def "MAV_CMD_DO_SET_MISSION_CURRENT and MISSION_SET_CURRENT take PX4's seq, the first item 0"() {
        given:
        def d = px4()
        d.upload(survey())

        when:
        def ack = d.command(MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, [2])

        then:
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.missionCurrent() == 3
        current(d).seq == 2

        when:
        int from = d.mark()
        d.handle(new msg_mission_set_current(target_system: 1, target_component: 1, seq: 0))

        then:
        d.since(from, msg_mission_current).last().seq == 0
        d.vehicle.missionCurrent() == 1
    }

    def "a pilot's takeover holds a PX4 vehicle in AUTO.LOITER, or the PX4 mode named, and hands AUTO.MISSION back"() {
        given:
        def options = PX4.withFault(SimFault.parse(fault))
        SimFault.parse(fault).checkFor(VehicleKind.COPTER, Autopilot.PX4)
        def d = new SimDriver(VehicleKind.COPTER, options)
        d.upload([rel(0, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10), rel(1, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, 0, 0, 10)])
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])
        List<String> modes = []

        when: 'during the takeover, 12 to 17 s after arming, and after it'
        d.run(14)
        modes << d.vehicle.modeName()
        d.run(10)
        modes << d.vehicle.modeName()

        then:
        modes == [held, 'AUTO.MISSION']

        where:
        fault                      | held
        'takeover=5@12'            | 'AUTO.LOITER'
        'takeover=5,posctl@12'     | 'POSCTL'
    }

    def "a takeover names a mode PX4 has"() {
        when:
        SimFault.parse('takeover=5,loiter@12').checkFor(VehicleKind.COPTER, Autopilot.PX4)

        then:
        def e = thrown(IllegalArgumentException)
        e.message.startsWith("PX4 multicopter has no mode 'loiter': expected one of ")
    }

    def "AUTOPILOT_VERSION has PX4's capabilities, FTP among them, but FTP has no @MISSION file"() {
        given:
        def d = px4()

        when:
        d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [msg_autopilot_version.MAVLINK_MSG_ID_AUTOPILOT_VERSION])
        int from = d.mark()
        d.handle(SimFtpServerSpec.ftpRequest(1, OPEN_FILE_RO, [data: '@MISSION/mission.dat', session: 1]))
        def reply = SimFtpPacket.of(d.since(from, msg_file_transfer_protocol).last())

        then:
        d.since(0, msg_autopilot_version).last().capabilities == 0xe8ff
        (d.since(0, msg_autopilot_version).last().capabilities & MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_FTP) != 0
        reply.opcode() == NAK
        reply.data()[0] == FILE_NOT_FOUND
    }

    def "a standard VTOL flies VTOL_TAKEOFF, a leg as a fixed wing and VTOL_LAND, and disarms on the ground"() {
        given:
        def d = px4(VehicleKind.QUADPLANE)
        d.command(MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL, [msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE, 1_000_000])
        d.upload([rel(0, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, 0, 0, 30), rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 1500, 0, 30),
                  rel(2, MAV_CMD.MAV_CMD_NAV_VTOL_LAND, 1500, 0, 0)])
        int from = d.mark()

        when:
        d.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0])
        d.runUntil(600, 'the disarm') { !d.vehicle.armed() }
        def states = runs(d.since(from, msg_extended_sys_state).collect { it.vtol_state as int })

        then:
        states == [MAV_VTOL_STATE.MAV_VTOL_STATE_MC, MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_FW, MAV_VTOL_STATE.MAV_VTOL_STATE_FW,
                   MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_MC, MAV_VTOL_STATE.MAV_VTOL_STATE_MC]
        runs(d.since(from, msg_mission_item_reached)*.seq) == [0, 1, 2]
        d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE
    }
}
