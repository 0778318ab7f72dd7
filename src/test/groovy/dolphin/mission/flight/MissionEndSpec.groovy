package dolphin.mission.flight

import dolphin.mission.model.MissionItem
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import java.time.Duration
import spock.lang.Specification

/**
 * The end of a mission per family, fed with the vehicle's reports in the order real ArduPilot SITL
 * sends them (docs/mavlink.md, "How each family flies a mission"): no vehicles, no sockets, the
 * clock is a number.
 */
class MissionEndSpec extends Specification {

    static final long S = 1_000_000_000L
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final int ON_GROUND = MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND
    static final int IN_AIR = MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR
    static final int LANDING = MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING
    static final int ACTIVE = MISSION_STATE.MISSION_STATE_ACTIVE
    static final int COMPLETE = MISSION_STATE.MISSION_STATE_COMPLETE

    /** Home, take-off, two waypoints, then the given last command. */
    static List<MissionItem> mission(int lastCommand) {
        def at = { int seq, int cmd, double north, double up ->
            MissionItem.at(seq, cmd, HOME.displace(north, 0, -up), 0, 0, 0, 0)
        }
        [at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0, 0), at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 20),
         at(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 50, 20), at(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 20),
         at(4, lastCommand, 100, lastCommand == MAV_CMD.MAV_CMD_NAV_LAND ? 0 : 20)]
    }

    static MissionEnd end(VehicleFamily family, int lastCommand) {
        new MissionEnd(FlightRules.of(family), mission(lastCommand), '1', Duration.ofSeconds(60))
    }

    /** A snapshot: heartbeat (armed, custom mode), MISSION_CURRENT, landed state, height above home. */
    static VehicleState state(VehicleFamily family, Map m) {
        def hb = new msg_heartbeat()
        hb.base_mode = (short) ((m.armed ? 128 : 0) | 1)
        hb.custom_mode = dolphin.mavlink.Autopilot.ARDUPILOT.modes(family).number(m.mode as String).asLong
        double up = (m.up ?: 0) as double
        def s = VehicleState.initial(family).withHeartbeat(hb, 0)
                .withMissionCurrent((m.seq ?: 0) as int, 4, (m.mission ?: ACTIVE) as int)
                .withExtendedState((m.landed ?: IN_AIR) as int, 0)
                .withPosition(HOME.displace((m.north ?: 0) as double, 0, -up), up, Double.NaN, 0)
        (m.texts ?: []).each { s = s.withStatusText(it as String) }
        s
    }

    def "copter, mission ending in LAND: done once the LAND was current and the copter is down and disarmed, though LAND is never reported reached"() {
        given: 'the frames of a real ArduCopter landing: LAND current, LANDING, then on disarm the mission restarts at item 2'
        def end = end(VehicleFamily.COPTER, MAV_CMD.MAV_CMD_NAV_LAND)
        def c = { Map m -> state(VehicleFamily.COPTER, [mode: 'AUTO'] + m) }

        expect:
        end.judge(c(armed: true, seq: 3, up: 20), 2, true, 1 * S).running()
        end.judge(c(armed: true, seq: 4, up: 20), 3, true, 2 * S).running()
        end.judge(c(armed: true, seq: 4, up: 5, landed: LANDING), 3, true, 10 * S).running()
        end.judge(c(armed: true, seq: 2, up: 0, landed: LANDING), 3, true, 20 * S).running()
        end.judge(c(armed: true, seq: 2, up: 0, landed: ON_GROUND), 3, true, 20 * S).running()
        end.judge(c(armed: false, seq: 2, up: 0, landed: ON_GROUND), 3, true, 21 * S).done
    }

    def "a landing that makes no progress for the stall limit is an error saying where the vehicle is"() {
        given:
        def end = end(VehicleFamily.COPTER, MAV_CMD.MAV_CMD_NAV_LAND)
        def c = { Map m -> state(VehicleFamily.COPTER, [mode: 'AUTO', armed: true, seq: 4, landed: LANDING] + m) }

        expect: 'descending is progress'
        end.judge(c(up: 12), 3, true, 0).running()
        end.judge(c(up: 10), 3, true, 50 * S).running()
        end.judge(c(up: 10.5), 3, true, 100 * S).running()

        when: 'stuck 10 m up for more than 60 s'
        def v = end.judge(c(up: 10.2), 3, true, 111 * S)

        then:
        v.error == 'vehicle 1 did not finish item 4 of 4 (NAV_LAND): no progress for 60 s: armed, AUTO, landed state LANDING, 10.2 m above home'
    }

    def "a landing held out of AUTO by someone else is no stalled landing: its clock starts again in AUTO"() {
        given:
        def end = end(VehicleFamily.COPTER, MAV_CMD.MAV_CMD_NAV_LAND)
        def c = { Map m -> state(VehicleFamily.COPTER, [armed: true, seq: 4, landed: LANDING, up: 10] + m) }

        expect: 'held in LOITER 10 m up for 100 s, then 59 s in AUTO without progress'
        end.judge(c(mode: 'AUTO'), 3, true, 0).running()
        end.judge(c(mode: 'LOITER'), 3, false, 1 * S).running()
        end.judge(c(mode: 'LOITER'), 3, false, 100 * S).running()
        end.judge(c(mode: 'AUTO'), 3, true, 101 * S).running()
        end.judge(c(mode: 'AUTO'), 3, true, 160 * S).running()

        and: 'past 60 s in AUTO it is a stalled landing'
        end.judge(c(mode: 'AUTO'), 3, true, 162 * S).error.startsWith('vehicle 1 did not finish item 4 of 4 (NAV_LAND): no progress for 60 s')
    }

    def "plane: RTL in the same tick as, and before, the last MISSION_ITEM_REACHED is the plane's own end: done"() {
        given:
        def end = end(VehicleFamily.PLANE, MAV_CMD.MAV_CMD_NAV_WAYPOINT)
        def p = { Map m -> state(VehicleFamily.PLANE, [armed: true, up: 60] + m) }

        expect: 'flying item 4 in AUTO, then the heartbeat says RTL with item 4 current'
        end.judge(p(mode: 'AUTO', seq: 4), 3, true, 10 * S).running()
        end.judge(p(mode: 'RTL', seq: 4), 3, false, 10 * S + 1000).running()

        and: 'the last item reached arrives'
        end.judge(p(mode: 'RTL', seq: 4), 4, false, 10 * S + 2000).done
    }

    def "plane: COMPLETE after the RTL ends it too"() {
        given:
        def end = end(VehicleFamily.PLANE, MAV_CMD.MAV_CMD_NAV_WAYPOINT)
        def p = { Map m -> state(VehicleFamily.PLANE, [armed: true, up: 60] + m) }
        end.judge(p(mode: 'AUTO', seq: 4), 3, true, 10 * S)

        expect:
        end.judge(p(mode: 'RTL', seq: 4), 3, false, 10 * S).running()
        end.judge(p(mode: 'RTL', seq: 4, mission: COMPLETE), 3, false, 11 * S).done
    }

    def "rover: done at COMPLETE, staying in AUTO"() {
        given:
        def end = end(VehicleFamily.ROVER, MAV_CMD.MAV_CMD_NAV_WAYPOINT)
        def r = { Map m -> state(VehicleFamily.ROVER, [armed: true, mode: 'AUTO', landed: ON_GROUND] + m) }

        expect:
        end.judge(r(seq: 4), 3, true, 1 * S).running()
        end.judge(r(seq: 4, mission: COMPLETE), 3, true, 2 * S).done
    }

    def "a rover's NAV_LAND is not a landing: it is done when the item is reached"() {
        given:
        def end = end(VehicleFamily.ROVER, MAV_CMD.MAV_CMD_NAV_LAND)
        def r = { Map m -> state(VehicleFamily.ROVER, [armed: true, mode: 'AUTO', landed: ON_GROUND] + m) }

        expect:
        end.judge(r(seq: 4), 3, true, 1 * S).running()
        end.judge(r(seq: 4), 4, true, 2 * S).done
    }

    def "a mission ending in an unlimited loiter never ends by itself"() {
        given:
        def end = end(VehicleFamily.COPTER, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM)
        def c = { Map m -> state(VehicleFamily.COPTER, [armed: true, mode: 'AUTO', up: 20] + m) }

        expect:
        end.judge(c(seq: 4), 3, true, 1 * S).running()
        end.judge(c(seq: 4), 4, true, 600 * S).running()
    }

    def "COMPLETE from before the mission started (an earlier mission's) does not end it"() {
        given:
        def end = end(VehicleFamily.COPTER, MAV_CMD.MAV_CMD_NAV_WAYPOINT)
        def c = { Map m -> state(VehicleFamily.COPTER, [armed: true, mode: 'AUTO', up: 20] + m) }

        expect:
        end.judge(c(seq: 0, mission: COMPLETE), 0, true, 1 * S).running()
        end.judge(c(seq: 1), 0, true, 2 * S).running()
        end.judge(c(seq: 4, mission: COMPLETE), 0, true, 3 * S).done
    }
}
