package dolphin.sim

import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_MODE_FLAG
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MAV_STATE
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.enums.SUB_MODE
import com.MAVLink.minimal.msg_heartbeat
import com.MAVLink.standard.msg_global_position_int
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mission.model.MissionItem
import spock.lang.Specification

/**
 * The simulated ArduSub on a fake clock, against what ArduSub SITL did (docs/decisions.md, "ArduSub
 * behaviour"): arming, the modes that need a position, depths under water, the altitude frames
 * Sub::start_command accepts, AUTO while disarmed, the end of a mission, surfacing; and the dive
 * silence of SimOptions.
 */
class SimSubSpec extends Specification {

    /** The report's underwater example: off Comporta, at sea level. */
    static final Position COMPORTA = Position.fromDegrees(38.43462, -8.86118, 0)
    static final int RELATIVE = MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT

    static MissionItem item(int seq, double north, double east, double z, int frame = RELATIVE,
                            int command = MAV_CMD.MAV_CMD_NAV_WAYPOINT, float p1 = 0) {
        def p = COMPORTA.displace(north, east, 0)
        new MissionItem(seq, command, frame, p1, 0, 0, 0, MissionItem.degE7(p.latitudeDegrees()),
                MissionItem.degE7(p.longitudeDegrees()), (float) z, true)
    }

    static MissionItem home() {
        MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, COMPORTA, 0, 0, 0, 0)
    }

    /** The recording's mission: three waypoints 30 m apart, 10 m deep. */
    static List<MissionItem> dive(int frame = RELATIVE) {
        [home(), item(1, 30, 0, -10, frame), item(2, 30, 30, -10, frame), item(3, 0, 30, -10, frame)]
    }

    static SimDriver sub(SimOptions options = SimOptions.DEFAULT) {
        def d = new SimDriver(VehicleKind.SUB, options, COMPORTA)
        d.run(1)
        d
    }

    static int setMode(SimDriver d, int mode) {
        d.command(MAV_CMD.MAV_CMD_DO_SET_MODE, [MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, mode]).result
    }

    static double depth(SimDriver d) {
        -(d.vehicle.position().hae() - COMPORTA.hae())
    }

    static boolean atSurface(SimDriver d) {
        d.vehicle.position().hae() == COMPORTA.hae()
    }

    static double horizontal(Position a, Position b) {
        def ned = a.displacementTo(b)
        Math.hypot(ned[0], ned[1])
    }

    static List<msg_mission_current> currents(SimDriver d, int from) {
        d.since(from, msg_mission_current)
    }

    def "it boots a submarine in MANUAL, disarmed, and arms before its position estimate without a PreArm word"() {
        given:
        def d = sub(SimOptions.DEFAULT.withWarmup(41))
        def hb = d.since(0, msg_heartbeat).first()

        when: 'armed 3 s after boot, long before the position estimate'
        d.run(2)
        def ack = d.arm()
        d.run(40)

        then:
        hb.type == MAV_TYPE.MAV_TYPE_SUBMARINE
        hb.custom_mode == SUB_MODE.SUB_MODE_MANUAL
        (hb.base_mode & MAV_MODE_FLAG.MAV_MODE_FLAG_SAFETY_ARMED) == 0
        hb.system_status == MAV_STATE.MAV_STATE_STANDBY
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.texts() == ['Arming motors']
        d.since(0, msg_heartbeat).last().system_status == MAV_STATE.MAV_STATE_ACTIVE
    }

    def "#mode is refused before the position estimate (and AUTO without a mission): FAILED and '#text'"() {
        given:
        def d = sub(SimOptions.DEFAULT.withWarmup(41))
        if (mission) {
            assert d.upload(dive()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        }
        d.run(wait)
        int from = d.mark()

        when:
        int result = setMode(d, mode)

        then:
        result == MAV_RESULT.MAV_RESULT_FAILED
        d.vehicle.mode() == SUB_MODE.SUB_MODE_MANUAL
        // STATUSTEXT carries 50 characters, as ArduPilot's does
        d.since(from, msg_statustext).collect { [it.severity, it.text] } == [[MAV_SEVERITY.MAV_SEVERITY_WARNING as short, text.take(50)]]

        where:
        mode                      | mission | wait || text
        SUB_MODE.SUB_MODE_AUTO    | true    | 20   || 'Mode change failed: Auto requires position'
        SUB_MODE.SUB_MODE_POSHOLD | false   | 20   || 'Mode change failed: Position Hold requires position'
        SUB_MODE.SUB_MODE_GUIDED  | false   | 20   || 'Mode change failed: Guided requires position'
        SUB_MODE.SUB_MODE_AUTO    | false   | 45   || 'Flight mode change failed Auto'
    }

    def "ALT_HOLD, MANUAL and SURFACE need no position; with one and a mission AUTO is accepted"() {
        given:
        def d = sub(SimOptions.DEFAULT.withWarmup(41))
        assert d.upload(dive()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED

        expect:
        setMode(d, SUB_MODE.SUB_MODE_ALT_HOLD) == MAV_RESULT.MAV_RESULT_ACCEPTED
        setMode(d, SUB_MODE.SUB_MODE_SURFACE) == MAV_RESULT.MAV_RESULT_ACCEPTED
        setMode(d, SUB_MODE.SUB_MODE_MANUAL) == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.run(41)
        setMode(d, SUB_MODE.SUB_MODE_AUTO) == MAV_RESULT.MAV_RESULT_ACCEPTED
    }

    def "it dives the recorded mission: 10 m down in about 25 s, 30 m legs in about 35 s, each waypoint reached at depth, then it holds armed in AUTO"() {
        given:
        def d = sub()
        assert d.command(MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL, [msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT, 1_000_000])
                .result == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert d.upload(dive()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        int from = d.mark()

        when:
        assert setMode(d, SUB_MODE.SUB_MODE_AUTO) == MAV_RESULT.MAV_RESULT_ACCEPTED
        double start = d.seconds()
        d.runUntil(40, '10 m depth') { depth(d) >= 9.95 }
        double down = d.seconds() - start
        d.runUntil(60, 'item 1 reached') { d.since(from, msg_mission_item_reached).any { it.seq == 1 } }
        double first = d.seconds() - start
        d.runUntil(60, 'item 2 reached') { d.since(from, msg_mission_item_reached).any { it.seq == 2 } }
        double second = d.seconds() - start - first
        d.runUntil(60, 'item 3 reached') { d.since(from, msg_mission_item_reached).any { it.seq == 3 } }
        d.run(1)
        def end = d.vehicle.position()
        int after = d.mark()
        d.run(45)

        then: 'said and reported as ArduSub does'
        d.texts(from).containsAll(['Mission: 1 WP', 'Reached command #1', 'Mission: 2 WP', 'Reached command #2', 'Mission: 3 WP',
                                   'Reached command #3'])
        d.since(from, msg_mission_item_reached)*.seq == [1, 2, 3]
        currents(d, from).last().seq == 3
        currents(d, from).last().mission_state == MISSION_STATE.MISSION_STATE_COMPLETE

        and: 'at the recording speeds'
        down > 22 && down < 28
        first > 32 && first < 38
        second > 32 && second < 38

        and: 'GLOBAL_POSITION_INT under water: relative_alt and alt (AMSL, home at sea level) negative'
        def p = d.since(after, msg_global_position_int).last()
        Math.abs(p.relative_alt + 10000) < 1000
        Math.abs(p.alt + 10000) < 1000

        and: 'it holds there, armed in AUTO, 45 s on'
        horizontal(d.vehicle.position(), end) < 0.1
        Math.abs(depth(d) - 10) < 1
        d.vehicle.armed()
        d.vehicle.mode() == SUB_MODE.SUB_MODE_AUTO
        d.since(after, msg_mission_item_reached).empty
    }

    def "items in a frame other than relative to home or terrain say 'Bad alt frame' and are skipped in the same update: COMPLETE at once, nothing reached"() {
        given:
        def d = sub()
        assert d.upload(dive(MAV_FRAME.MAV_FRAME_GLOBAL_INT)) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        int from = d.mark()

        when:
        assert setMode(d, SUB_MODE.SUB_MODE_AUTO) == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.run(0.1)

        then:
        d.texts(from) == ['Mission: 1 WP', 'Bad alt frame', 'Mission: 2 WP', 'Bad alt frame', 'Mission: 3 WP', 'Bad alt frame']
        d.since(from, msg_statustext).findAll { it.text == 'Bad alt frame' }*.severity.every { it == MAV_SEVERITY.MAV_SEVERITY_WARNING }
        d.since(from, msg_mission_item_reached).empty
        currents(d, from).collect { [it.seq, it.total, it.mission_state] }.unique() == [[3, 3, MISSION_STATE.MISSION_STATE_COMPLETE]]

        and: 'armed in AUTO at the surface, the mission not restarted'
        d.run(10)
        d.vehicle.armed()
        d.vehicle.mode() == SUB_MODE.SUB_MODE_AUTO
        atSurface(d)
        d.texts(from).count { it.startsWith('Mission:') } == 3
    }

    def "#what: '#refusal', skipped, and the next item flown"() {
        given:
        def d = sub()
        assert d.upload([home(), refused, item(2, 5, 0, -2)]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        int from = d.mark()

        when:
        setMode(d, SUB_MODE.SUB_MODE_AUTO)
        d.runUntil(30, 'item 2 reached') { d.since(from, msg_mission_item_reached).any { it.seq == 2 } }

        then:
        d.texts(from).take(3) == [started, refusal, 'Mission: 2 WP']
        d.since(from, msg_mission_item_reached)*.seq == [2]
        horizontal(d.vehicle.position(), COMPORTA.displace(5, 0, 0)) < 1
        Math.abs(depth(d) - 2) < 1

        where:
        what                                | refused                                                                       || started           | refusal
        'a height above home'               | item(1, 0, 0, 5)                                                              || 'Mission: 1 WP'   | 'Alt above home must be negative'
        'a negative height above terrain'   | item(1, 0, 0, -3, MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT)                  || 'Mission: 1 WP'   | 'Alt above terrain must be positive'
        'AMSL (MAV_FRAME_GLOBAL)'           | item(1, 0, 0, -10, MAV_FRAME.MAV_FRAME_GLOBAL)                                || 'Mission: 1 WP'   | 'Bad alt frame'
        'NAV_TAKEOFF'                       | item(1, 0, 0, -1, RELATIVE, MAV_CMD.MAV_CMD_NAV_TAKEOFF)                      || 'Mission: 1 Takeoff' | 'Ignoring command 22'
        'NAV_RETURN_TO_LAUNCH, no location' | new MissionItem(1, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, RELATIVE, 0, 0, 0, 0, 0, 0, 0, true) || 'Mission: 1 RTL' | 'Bad alt frame'
    }

    def "a terrain item, with no terrain data in SITL: the mission stops there (NOT_STARTED), still in AUTO"() {
        given:
        def d = sub()
        assert d.upload([home(), item(1, 10, 0, 5, MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT), item(2, 20, 0, -2)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        int from = d.mark()

        when:
        setMode(d, SUB_MODE.SUB_MODE_AUTO)
        d.run(10)

        then:
        d.texts(from) == ['Mission: 1 WP', 'Terrain data (rangefinder) not available', 'Attempting auto failsafe recovery']
        currents(d, from).last().seq == 1
        currents(d, from).last().mission_state == MISSION_STATE.MISSION_STATE_NOT_STARTED
        d.vehicle.mode() == SUB_MODE.SUB_MODE_AUTO
        atSurface(d)
    }

    def "AUTO while disarmed runs the whole mission through at once, without moving; AUTO again after COMPLETE starts at item 1"() {
        given:
        def d = sub()
        assert d.upload(dive()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        int from = d.mark()

        when:
        assert setMode(d, SUB_MODE.SUB_MODE_AUTO) == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.run(0.1)

        then:
        d.since(from, msg_mission_item_reached)*.seq == [1, 2, 3]
        d.texts(from) == ['Mission: 1 WP', 'Reached command #1', 'Mission: 2 WP', 'Reached command #2', 'Mission: 3 WP',
                          'Reached command #3']
        currents(d, from).last().mission_state == MISSION_STATE.MISSION_STATE_COMPLETE
        d.vehicle.position() == COMPORTA

        when: 'armed, MANUAL, then AUTO again'
        d.arm()
        setMode(d, SUB_MODE.SUB_MODE_MANUAL)
        int again = d.mark()
        setMode(d, SUB_MODE.SUB_MODE_AUTO)
        d.run(5)

        then: 'the mission starts over at item 1 and the sub dives'
        d.texts(again).first() == 'Mission: 1 WP'
        currents(d, again).last().seq == 1
        currents(d, again).last().mission_state == MISSION_STATE.MISSION_STATE_ACTIVE
        depth(d) > 1
    }

    def "disarmed at depth in AUTO: accepted, the mission reset and run through from item 1 at once; MISSION_CURRENT then seq 0 if it was complete"() {
        given:
        def d = sub()
        assert d.upload(dive()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        setMode(d, SUB_MODE.SUB_MODE_AUTO)
        d.run(20)
        assert depth(d) > 5
        int from = d.mark()

        when:
        def ack = d.command(MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, [0])
        d.run(1)

        then:
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        !d.vehicle.armed()
        d.since(from, msg_mission_item_reached)*.seq == [1, 2, 3]
        currents(d, from).last().mission_state == MISSION_STATE.MISSION_STATE_COMPLETE
        depth(d) > 5
    }

    def "NAV_LAND surfaces: to its position at the depth it is at, then straight up, reached at the surface, still armed in AUTO"() {
        given:
        def d = sub()
        assert d.upload([home(), item(1, 0, 0, -6), item(2, 10, 0, 0, RELATIVE, MAV_CMD.MAV_CMD_NAV_LAND)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        int from = d.mark()
        setMode(d, SUB_MODE.SUB_MODE_AUTO)
        d.runUntil(40, 'item 1 reached') { d.since(from, msg_mission_item_reached).any { it.seq == 1 } }
        double deep = depth(d)

        when:
        d.runUntil(20, 'the landing point at depth') { horizontal(d.vehicle.position(), COMPORTA.displace(10, 0, 0)) < 1 }
        double arrivedAt = depth(d)
        d.runUntil(40, 'item 2 reached') { d.since(from, msg_mission_item_reached).any { it.seq == 2 } }

        then:
        Math.abs(arrivedAt - deep) < 0.1
        atSurface(d)
        horizontal(d.vehicle.position(), COMPORTA.displace(10, 0, 0)) < 1
        d.vehicle.armed()
        d.vehicle.mode() == SUB_MODE.SUB_MODE_AUTO
        !d.texts(from).contains('Reached command #2')
    }

    def "SURFACE goes straight up and, at the surface, switches to ALT_HOLD; POSHOLD holds position and depth"() {
        given:
        def d = sub()
        assert d.upload([home(), item(1, 0, 0, -8)]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        setMode(d, SUB_MODE.SUB_MODE_AUTO)
        d.runUntil(40, 'mission complete') { d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE }
        def below = d.vehicle.position()

        when:
        assert setMode(d, SUB_MODE.SUB_MODE_POSHOLD) == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.run(20)

        then:
        d.vehicle.position() == below

        when:
        assert setMode(d, SUB_MODE.SUB_MODE_SURFACE) == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.runUntil(30, 'ALT_HOLD') { d.vehicle.mode() == SUB_MODE.SUB_MODE_ALT_HOLD }

        then:
        atSurface(d)
        horizontal(d.vehicle.position(), below) < 0.1
        d.vehicle.armed()
        d.since(0, msg_heartbeat).last().custom_mode == SUB_MODE.SUB_MODE_ALT_HOLD
    }

    def "it has no RTL: MAV_CMD_NAV_RETURN_TO_LAUNCH is UNSUPPORTED; MAV_CMD_NAV_LAND selects SURFACE"() {
        given:
        def d = sub()
        d.arm()

        expect:
        d.command(MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH).result == MAV_RESULT.MAV_RESULT_UNSUPPORTED
        d.vehicle.mode() == SUB_MODE.SUB_MODE_MANUAL
        d.command(MAV_CMD.MAV_CMD_NAV_LAND).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.vehicle.mode() == SUB_MODE.SUB_MODE_SURFACE
    }

    def "it never rises above the surface, whatever it is sent to"() {
        given:
        def d = sub()
        assert d.upload([home(), item(1, 10, 0, -3), item(2, 20, 0, 0)]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        setMode(d, SUB_MODE.SUB_MODE_AUTO)
        double highest = -100

        when:
        d.runUntil(60, 'mission complete') {
            highest = Math.max(highest, d.vehicle.position().hae())
            d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE
        }

        then:
        highest == COMPORTA.hae()
        d.since(0, msg_global_position_int).every { it.relative_alt <= 0 }
    }

    def "dive silence: deeper than the given metres it sends and hears nothing; shallower it is heard again"() {
        given:
        def d = sub(SimOptions.DEFAULT.withDiveSilence(3))
        assert d.upload([home(), item(1, 0, 0, -6), item(2, 0, 0, -1, RELATIVE, MAV_CMD.MAV_CMD_NAV_LOITER_TIME, 20),
                         item(3, 0, 0, 0)]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        setMode(d, SUB_MODE.SUB_MODE_AUTO)
        d.runUntil(20, '3 m down') { depth(d) > 3.2 }
        int from = d.mark()

        when: 'below 3 m'
        d.run(5)
        def ack = d.command(MAV_CMD.MAV_CMD_NAV_LAND)

        then: 'not a frame out, and the command not heard'
        d.mark() == from
        ack == null
        d.vehicle.mode() == SUB_MODE.SUB_MODE_AUTO

        when: 'back up to 1 m'
        d.runUntil(40, 'shallower than 3 m') { depth(d) < 2.9 }
        d.run(2)

        then: 'heard again'
        d.since(from, msg_heartbeat).size() >= 1
        d.command(MAV_CMD.MAV_CMD_NAV_LAND).result == MAV_RESULT.MAV_RESULT_ACCEPTED
    }

    def "the boat is ArduRover with MAV_TYPE_SURFACE_BOAT in its heartbeat; the rover keeps MAV_TYPE_GROUND_ROVER"() {
        expect:
        with(new SimDriver(kind)) {
            run(1)
            since(0, msg_heartbeat).first().type == type
            vehicle.kind().family() == VehicleFamily.ROVER
        }

        where:
        kind               || type
        VehicleKind.BOAT   || MAV_TYPE.MAV_TYPE_SURFACE_BOAT
        VehicleKind.ROVER  || MAV_TYPE.MAV_TYPE_GROUND_ROVER
    }

    def "'#name' is #kind"() {
        expect:
        VehicleKind.parse(name) == kind

        where:
        name      || kind
        'sub'     || VehicleKind.SUB
        'ArduSub' || VehicleKind.SUB
        'boat'    || VehicleKind.BOAT
    }
}
