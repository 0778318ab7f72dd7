package dolphin.sim

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_extended_sys_state
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_param_request_read
import com.MAVLink.common.msg_param_value
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_PARAM_TYPE
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.enums.MAV_VTOL_STATE
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.enums.PLANE_MODE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mission.model.MissionItem
import spock.lang.Specification

/**
 * The simulated QuadPlane on a fake clock, against what ArduPlane SITL did with quadplane.parm
 * (docs/mavlink.md, "The simulated fleet"): its identity and parameters, the VTOL take-off, the
 * transition, the VTOL landing with its stages, texts and states, the arming check of a landing too
 * close to the waypoint before it (and the missions that pass it), QRTL, RTL and QLOITER.
 */
class SimQuadPlaneSpec extends Specification {

    static final int RELATIVE = MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
    static final Position HOME = SimDriver.HOME

    static MissionItem item(int seq, int command, double north, double east, double z, float p1 = 0) {
        def p = HOME.displace(north, east, 0)
        new MissionItem(seq, command, RELATIVE, p1, 0, 0, 0, MissionItem.degE7(p.latitudeDegrees()),
                MissionItem.degE7(p.longitudeDegrees()), (float) z, true)
    }

    static MissionItem home() {
        MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0)
    }

    /** A take-off to 30 m where it stands (lat, lon 0), as the findings' runs had it. */
    static MissionItem takeoff(int command = MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF) {
        new MissionItem(1, command, RELATIVE, 0, 0, 0, 0, 0, 0, 30, true)
    }

    /** SITL's run "good": take-off, 400 m north, 400 m east, a VTOL landing at home. */
    static List<MissionItem> good(int takeoffCommand = MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, int landCommand = MAV_CMD.MAV_CMD_NAV_VTOL_LAND) {
        [home(), takeoff(takeoffCommand), item(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 400, 0, 40),
         item(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 400, 400, 40), item(4, landCommand, 0, 0, 0)]
    }

    /** A QuadPlane one second after boot, streaming EXTENDED_SYS_STATE at 5 Hz. */
    static SimDriver quadplane() {
        def d = new SimDriver(VehicleKind.QUADPLANE)
        d.run(1)
        d.command(MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL, [msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE, 200_000])
        d
    }

    static SimDriver armedInAuto(List<MissionItem> mission) {
        def d = quadplane()
        assert d.upload(mission) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        assert d.setMode(PLANE_MODE.PLANE_MODE_AUTO).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d
    }

    /** The values of a field of EXTENDED_SYS_STATE since {@code from}, each change once. */
    static List<Integer> changes(SimDriver d, int from, Closure<Integer> field) {
        d.since(from, msg_extended_sys_state).collect(field).inject([]) { List l, v -> l && l.last() == v ? l : l + [v] }
    }

    static MAVLinkMessage paramRead(String name, int index = -1, int sysid = 1) {
        def r = new msg_param_request_read(target_system: sysid, target_component: 1, param_index: index)
        r.setParam_Id(name)
        r
    }

    static double heightOf(SimDriver d) {
        d.vehicle.position().hae() - HOME.hae()
    }

    static List<String> flightTexts(SimDriver d, int from = 0) {
        d.texts(from).findAll { !it.startsWith('Mission: ') && it != 'Flight plan received' }
                .collect { it.replaceAll(/ (v|d|sd|h|dc|airspeed|reached|dist)[= ][-0-9.]+m?/, ' $1') }
    }

    def "it says FIXED_WING, as ArduPlane does with Q_MAV_TYPE 0, boots in FLY_BY_WIRE_A (SITL's mode switch), and tells its VTOL state: FW in FLY_BY_WIRE_A, MC on the ground in AUTO"() {
        given:
        def d = quadplane()
        d.run(1)
        def hb = d.since(0, msg_heartbeat).first()
        def atBoot = d.since(0, msg_extended_sys_state).last()

        when:
        d.upload(good())
        d.setMode(PLANE_MODE.PLANE_MODE_AUTO)
        d.run(1)

        then:
        hb.type == MAV_TYPE.MAV_TYPE_FIXED_WING
        hb.custom_mode == PLANE_MODE.PLANE_MODE_FLY_BY_WIRE_A
        VehicleKind.QUADPLANE.family() == VehicleFamily.VTOL
        VehicleKind.QUADPLANE.family().firmware() == VehicleFamily.PLANE
        atBoot.vtol_state == MAV_VTOL_STATE.MAV_VTOL_STATE_FW
        atBoot.landed_state == MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND
        d.since(0, msg_extended_sys_state).last().vtol_state == MAV_VTOL_STATE.MAV_VTOL_STATE_MC
    }

    def "a plane and a copter say no VTOL state (UNDEFINED)"() {
        given:
        def d = new SimDriver(kind)
        d.command(MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL, [msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE, 200_000])
        d.run(1)

        expect:
        d.since(0, msg_extended_sys_state)*.vtol_state.unique() == [MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED as short]

        where:
        kind << [VehicleKind.PLANE, VehicleKind.COPTER]
    }

    def "PARAM_REQUEST_READ of #name by name is answered with #value as #type, index -1 (65535 as a uint16) and the count of its parameters"() {
        given:
        def d = quadplane()
        int from = d.mark()

        when:
        d.handle(paramRead(name))

        then:
        def answers = d.since(from, msg_param_value)
        answers.size() == 1
        with(answers[0]) {
            getParam_Id() == name
            param_value == value as float
            param_type == type
            param_index == 65535
            param_count == QuadPlaneFirmware.PARAMS.size()
        }

        where:
        name              || value | type
        'Q_ENABLE'        || 1     | MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT8
        'AIRSPEED_CRUISE' || 25    | MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32
        'TECS_LAND_ARSPD' || -1    | MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32
        'Q_TRANS_DECEL'   || 2     | MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32
        'Q_OPTIONS'       || 0     | MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT32
        'Q_RTL_MODE'      || 0     | MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT8
    }

    def "a parameter it does not have, by name or past the last index, gets no answer; one by index comes with its name and index"() {
        given:
        def d = quadplane()
        int from = d.mark()

        when:
        d.handle(paramRead('NO_SUCH_PARAM'))
        d.handle(paramRead('', QuadPlaneFirmware.PARAMS.size()))
        d.handle(paramRead('Q_ENABLE', -1, 2))
        d.handle(paramRead('', 1))

        then:
        d.since(from, msg_param_value).collect { [it.getParam_Id(), it.param_index, it.param_value] } == [['AIRSPEED_CRUISE', 1, 25f]]
    }

    def "a plane answers Q_ENABLE 0, and not the Q_ parameters it hides while Q_ENABLE is 0; a copter answers none"() {
        given:
        def plane = new SimDriver(VehicleKind.PLANE)
        def copter = new SimDriver(VehicleKind.COPTER)

        when:
        ['Q_ENABLE', 'Q_TRANS_DECEL'].each { plane.handle(paramRead(it)); copter.handle(paramRead(it)) }

        then:
        plane.since(0, msg_param_value).collect { [it.getParam_Id(), it.param_value, it.param_type] } ==
                [['Q_ENABLE', 0f, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT8 as short]]
        copter.since(0, msg_param_value).empty
    }

    def "the findings' mission: a vertical take-off, the transition, two waypoints as a plane, a VTOL landing at home; disarmed, it stays in AUTO at the landing, ACTIVE"() {
        given:
        def d = armedInAuto(good())
        long armedAt = d.now

        when:
        d.runUntil(200, 'the disarm') { !d.vehicle.armed() }
        double flight = (d.now - armedAt) / 1e9
        d.run(10)

        then: 'the texts of SITL run "good", in its order'
        flightTexts(d) == ['Throttle armed', 'Transition started airspeed', 'Transition airspeed reached', 'Transition done',
                           'Reached waypoint #2 dist', 'Reached waypoint #3 dist', 'VTOL approach d', 'VTOL airbrake v d sd h',
                           'VTOL position1 v d h dc', 'VTOL position2 started v d h', 'Land descend started', 'Land final started',
                           'SIM Hit ground at 0.500000 m/s', 'Land complete', 'Throttle disarmed']
        d.texts().contains('Mission: 1 VTOLTakeoff')
        d.texts().contains('Mission: 4 VTOLLand')
        d.texts().contains('Transition started airspeed 0.0')
        d.texts().contains('VTOL approach d=498.1') // SITL: 506.6; item 3 taken at the L1 distance, 84 m, SITL's at 85 to 88 m

        and: 'its states as SITL reported them: MC, TRANSITION_TO_FW, FW, TRANSITION_TO_MC, MC; TAKEOFF, IN_AIR, LANDING, ON_GROUND'
        changes(d, 0) { it.vtol_state } == [MAV_VTOL_STATE.MAV_VTOL_STATE_FW, MAV_VTOL_STATE.MAV_VTOL_STATE_MC,
                                            MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_FW, MAV_VTOL_STATE.MAV_VTOL_STATE_FW,
                                            MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_MC, MAV_VTOL_STATE.MAV_VTOL_STATE_MC]
        changes(d, 0) { it.landed_state } == [MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND, MAV_LANDED_STATE.MAV_LANDED_STATE_TAKEOFF,
                                              MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR, MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING,
                                              MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND]

        and: 'the landing never reached nor the mission complete; it stays at home, in AUTO (SITL: 121 s from arming)'
        d.since(0, msg_mission_item_reached)*.seq == [1, 2, 3]
        with(d.since(0, msg_mission_current).last()) {
            seq == 4
            mission_state == MISSION_STATE.MISSION_STATE_ACTIVE
        }
        d.vehicle.mode() == PLANE_MODE.PLANE_MODE_AUTO
        d.vehicle.position().horizontalDistanceTo(HOME) < 0.5
        heightOf(d) == 0
        flight > 100 && flight < 130
    }

    def "as a plane it takes a waypoint as ArduPlane does: flown over when the next leg goes straight on, at the L1 distance (84 m) before a turn of 90 degrees, in proportion before a smaller one; one a loop"() {
        given: 'item 3 two metres past item 2, within its acceptance distance when item 2 is reached'
        def d = armedInAuto([home(), takeoff(), item(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 400, 0, 40),
                             item(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 402, 0, 40), item(4, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 402, 400, 40),
                             item(5, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 802, 400, 40), item(6, MAV_CMD.MAV_CMD_NAV_VTOL_LAND, 1202, 800, 0)])

        when:
        d.runUntil(120, 'the landing') { d.vehicle.missionCurrent() == 6 }

        then: 'Plane::verify_nav_wp with AP_L1_Control::turn_distance (NAVL1_PERIOD 14, NAVL1_DAMPING 0.75, 25 m/s), or past the finish line'
        d.texts().findAll { it ==~ /(Reached|Passed) waypoint.*/ } == ['Passed waypoint #2 dist 0m', 'Reached waypoint #3 dist 1m',
                                                                      'Reached waypoint #4 dist 83m', 'Reached waypoint #5 dist 41m']

        and: 'AP_Mission verifies one nav item a loop: items 2 and 3 are reported one after the other, each on its own'
        def reached = d.sent.findAll { it.message instanceof msg_mission_item_reached }
        reached*.message*.seq == [1, 2, 3, 4, 5]
        reached[2].at - reached[1].at == SimDriver.TICK
    }

    def "the take-off climbs straight up at Q_PILOT_SPD_UP to 30 m above where it stands and is reached there, before the transition"() {
        given:
        def d = armedInAuto(good())

        when:
        d.runUntil(30, 'the take-off reached') { d.since(0, msg_mission_item_reached)*.seq == [1] }

        then:
        Math.abs(heightOf(d) - 30) < 0.1
        d.vehicle.position().horizontalDistanceTo(HOME) < 0.01
        d.seconds() > 1 + 30 / QuadPlaneFirmware.VTOL_CLIMB - 0.5
        d.texts().takeWhile { !it.startsWith('Mission: 2') }.every { !it.startsWith('Transition') }
    }

    def "NAV_TAKEOFF and NAV_LAND (#takeoff, #land) are flown as NAV_VTOL_TAKEOFF and NAV_VTOL_LAND are, as SITL's run fwwords was"() {
        given:
        def d = armedInAuto(good(takeoff, land))

        when:
        d.runUntil(200, 'the disarm') { !d.vehicle.armed() }

        then:
        flightTexts(d) == flightTexts(armedInAuto(good()).with { runUntil(200, 'the disarm') { !vehicle.armed() }; it })
        d.texts().contains('Mission: 1 Takeoff')
        d.texts().contains('Mission: 4 Land')

        where:
        takeoff                          | land
        MAV_CMD.MAV_CMD_NAV_TAKEOFF      | MAV_CMD.MAV_CMD_NAV_LAND
    }

    /** Take-off, a waypoint 400 m north, one {@code last} metres north of home, {@code between} items, a landing at home. */
    static List<MissionItem> landingAfter(double last, int landCommand, List<Integer> between = []) {
        def items = [home(), takeoff(), item(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 400, 0, 40), item(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, last, 0, 40)]
        between.each { command -> items << MissionItem.command(items.size(), command, MAV_VTOL_STATE.MAV_VTOL_STATE_MC, 0, 0, 0) }
        items << item(items.size(), landCommand, 0, 0, 0)
        items
    }

    def "a landing #distance m after a waypoint is refused at arming with SITL's text (min 117 m: 0.75 v²/(2 Q_TRANS_DECEL), v = AIRSPEED_CRUISE 25)"() {
        given:
        def d = quadplane()
        d.upload(landingAfter(distance, land))
        d.setMode(PLANE_MODE.PLANE_MODE_AUTO)
        int from = d.mark()

        when:
        def ack = d.arm()

        then:
        ack.result == MAV_RESULT.MAV_RESULT_FAILED
        d.texts(from) == ['Arm: VTOL land too short, min 117m']
        !d.vehicle.armed()

        where:
        distance | land
        60       | MAV_CMD.MAV_CMD_NAV_VTOL_LAND
        60       | MAV_CMD.MAV_CMD_NAV_LAND
        116      | MAV_CMD.MAV_CMD_NAV_VTOL_LAND
    }

    def "a landing #distance m after the waypoint, after it with #between between, arms (AP_Arming_Plane checks only a NAV_WAYPOINT right before a landing)"() {
        given:
        def d = quadplane()
        d.upload(landingAfter(distance, MAV_CMD.MAV_CMD_NAV_VTOL_LAND, between))
        d.setMode(PLANE_MODE.PLANE_MODE_AUTO)

        expect:
        d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.armed()

        where:
        distance | between
        118      | []
        400      | []
        60       | [MAV_CMD.MAV_CMD_DO_VTOL_TRANSITION]
        60       | [MAV_CMD.MAV_CMD_DO_CHANGE_SPEED]
    }

    def "in #mode it refuses to arm: '#text'"() {
        given:
        def d = quadplane()
        d.upload(mission)
        d.setMode(mode)
        int from = d.mark()

        when:
        def ack = d.arm()

        then:
        ack.result == MAV_RESULT.MAV_RESULT_FAILED
        d.texts(from) == [text]

        where:
        mode                        | mission                                                           || text
        PLANE_MODE.PLANE_MODE_AUTO  | [home(), item(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 400, 0, 40)]       || 'Arm: Auto missing takeoff waypoint'
        PLANE_MODE.PLANE_MODE_RTL   | good()                                                            || 'Arm: RTL mode not armable'
        PLANE_MODE.PLANE_MODE_QRTL  | good()                                                            || 'Arm: QRTL mode not armable'
    }

    def "landed at the end of its mission, it refuses to arm again in AUTO ('In landing sequence'); a change to MANUAL resets the mission, and it arms"() {
        given:
        def d = armedInAuto(good())
        d.runUntil(200, 'the disarm') { !d.vehicle.armed() }
        int from = d.mark()

        when:
        def inAuto = d.arm()
        d.setMode(PLANE_MODE.PLANE_MODE_MANUAL)
        d.run(1)
        def inManual = d.arm()

        then:
        inAuto.result == MAV_RESULT.MAV_RESULT_FAILED
        d.texts(from).take(2) == ['Arm: In landing sequence', 'In landing sequence: mission reset']
        with(d.since(from, msg_mission_current).last()) {
            seq == 0
            mission_state == MISSION_STATE.MISSION_STATE_NOT_STARTED
        }
        inManual.result == MAV_RESULT.MAV_RESULT_ACCEPTED
    }

    def "landed, a change to #mode, a mode that navigates by itself, leaves the mission at its landing (Plane::set_mode)"() {
        given:
        def d = armedInAuto(good())
        d.runUntil(200, 'the disarm') { !d.vehicle.armed() }
        int from = d.mark()

        when:
        d.setMode(mode)
        d.run(1)

        then:
        !d.texts(from).contains('In landing sequence: mission reset')
        d.vehicle.missionCurrent() == 4

        where:
        mode << [PLANE_MODE.PLANE_MODE_GUIDED, PLANE_MODE.PLANE_MODE_RTL]
    }

    def "QRTL in flight: home as a plane, the VTOL landing there, disarmed in QRTL; disarmed outside AUTO, its mission is reset (SITL run cutqrtl)"() {
        given:
        def d = armedInAuto(good())
        d.runUntil(60, 'waypoint 2') { d.since(0, msg_mission_item_reached)*.seq == [1, 2] }
        int from = d.mark()

        when:
        d.setMode(PLANE_MODE.PLANE_MODE_QRTL)
        d.runUntil(200, 'the disarm') { !d.vehicle.armed() }
        d.run(1)

        then:
        flightTexts(d, from) == ['VTOL approach d', 'VTOL airbrake v d sd h', 'VTOL position1 v d h dc', 'VTOL position2 started v d h',
                                 'Land descend started', 'Land final started', 'SIM Hit ground at 0.500000 m/s', 'Land complete',
                                 'Throttle disarmed']
        changes(d, from) { it.vtol_state } == [MAV_VTOL_STATE.MAV_VTOL_STATE_FW, MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_MC,
                                               MAV_VTOL_STATE.MAV_VTOL_STATE_MC]
        d.vehicle.mode() == PLANE_MODE.PLANE_MODE_QRTL
        d.vehicle.position().horizontalDistanceTo(HOME) < 0.5
        heightOf(d) == 0
        with(d.since(from, msg_mission_current).last()) {
            seq == 0
            mission_state == MISSION_STATE.MISSION_STATE_NOT_STARTED
        }
    }

    def "RTL with Q_RTL_MODE 0 circles home as a plane and does not land (SITL run cutrtl0: still flying 120 s later)"() {
        given:
        def d = armedInAuto(good())
        d.runUntil(60, 'waypoint 2') { d.since(0, msg_mission_item_reached)*.seq == [1, 2] }

        when:
        d.setMode(PLANE_MODE.PLANE_MODE_RTL)
        d.run(120)

        then:
        d.vehicle.armed()
        heightOf(d) > 30
        d.vehicle.position().horizontalDistanceTo(HOME) < 200
        d.since(0, msg_extended_sys_state).last().vtol_state == MAV_VTOL_STATE.MAV_VTOL_STATE_FW
    }

    def "QLOITER in flight hovers where it began: MC, and still there 30 s later"() {
        given:
        def d = armedInAuto(good())
        d.runUntil(60, 'waypoint 2') { d.since(0, msg_mission_item_reached)*.seq == [1, 2] }

        when:
        d.setMode(PLANE_MODE.PLANE_MODE_QLOITER)
        def began = d.vehicle.position()
        d.run(30)

        then:
        d.vehicle.position().horizontalDistanceTo(began) < 0.01
        Math.abs(d.vehicle.position().hae() - began.hae()) < 0.01
        d.since(0, msg_extended_sys_state).last().vtol_state == MAV_VTOL_STATE.MAV_VTOL_STATE_MC
        d.vehicle.armed()
    }

    def "'#name' is #kind"() {
        expect:
        VehicleKind.parse(name) == kind

        where:
        name         || kind
        'quadplane'  || VehicleKind.QUADPLANE
        'VTOL'       || VehicleKind.QUADPLANE
        'heli'       || VehicleKind.HELI
        'helicopter' || VehicleKind.HELI
    }
}
