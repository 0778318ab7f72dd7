package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import dolphin.mission.model.MissionItem
import java.time.Duration
import spock.lang.Specification
import spock.lang.Unroll

/**
 * The stall rule per family, on a clock that is a number: what must warn and fail (no progress
 * toward an item), and what must not (a long leg flown, a plane's climb, a sub's slow dive, a rover's
 * delay, a hold at a waypoint, a loiter, a vehicle held by someone else).
 */
class StallWatchSpec extends Specification {

    static final long S = 1_000_000_000L
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final Duration WARN = Duration.ofSeconds(20)
    static final Duration LIMIT = Duration.ofSeconds(60)

    /** Home, then the given item as item 1. */
    static StallWatch watch(VehicleFamily family, MissionItem item) {
        def items = [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0), item.withSeq(1)]
        new StallWatch(FlightRules.of(family), new ItemNames(items), '1', WARN, LIMIT)
    }

    static MissionItem waypoint(double north, double up, float hold = 0, float radius = 0) {
        MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME.displace(north, 0, -up), hold, radius, 0, 0)
    }

    /** In AUTO, armed, {@code north} metres north of home and {@code up} above it, heard at {@code t} seconds. */
    static VehicleState at(VehicleFamily family, double north, double up, long t = 0) {
        def hb = new msg_heartbeat()
        hb.base_mode = (short) 129
        hb.custom_mode = dolphin.mavlink.Autopilot.ARDUPILOT.modes(family).number('AUTO').asLong
        VehicleState.initial(family).withHeartbeat(hb, 0).withPosition(HOME.displace(north, 0, -up), up, Double.NaN, t * S)
    }

    /** The same state, its position heard at {@code t} seconds. */
    static VehicleState fresh(VehicleState s, long t) {
        s.withPosition(s.position(), s.relativeAlt(), s.heading(), t * S)
    }

    def "a position not heard for over 5 s is no evidence of a stall: a sub silent at depth is the link's to judge"() {
        given: 'the last position heard at 0 s, 200 m short of the waypoint'
        def w = watch(VehicleFamily.SUB, waypoint(500, -5))
        def silent = at(VehicleFamily.SUB, 300, -5, 0)

        expect:
        (0..120).every { t -> w.look(silent, 1, true, t * S) == StallWatch.Notice.NONE }
        (121..140).every { t -> w.look(fresh(silent, t), 1, true, t * S) == StallWatch.Notice.NONE }
        w.look(fresh(silent, 142), 1, true, 142 * S).warning != null
    }

    def "a copter that hangs 200 m short of its waypoint: one warning after 20 s, the error after 60 s, naming item and distance"() {
        given:
        def w = watch(VehicleFamily.COPTER, waypoint(500, 30))
        def s = at(VehicleFamily.COPTER, 300, 30)

        expect:
        w.look(fresh(s, 0), 1, true, 0) == StallWatch.Notice.NONE
        w.look(fresh(s, 20), 1, true, 20 * S) == StallWatch.Notice.NONE
        w.look(fresh(s, 21), 1, true, 21 * S).warning == 'no progress toward item 1 of 1 (NAV_WAYPOINT): 200 m from it, no closer for 20 s'
        w.look(fresh(s, 22), 1, true, 22 * S) == StallWatch.Notice.NONE
        w.look(fresh(s, 60), 1, true, 60 * S) == StallWatch.Notice.NONE
        w.look(fresh(s, 61), 1, true, 61 * S).error == 'vehicle 1 stalled: no progress toward item 1 of 1 (NAV_WAYPOINT) for 60 s, 200 m from it' +
                ' (the stall limit): armed, AUTO, landed state UNDEFINED, 30.0 m above home'
    }

    @Unroll
    def "hanging near a waypoint it should pass is a stall: #what"() {
        given:
        def w = watch(family, item)

        expect:
        (0..20).every { t -> w.look(at(family, north, up, t), 1, true, t * S) == StallWatch.Notice.NONE }
        w.look(at(family, north, up, 21), 1, true, 21 * S).warning.startsWith('no progress toward item 1 of 1 (NAV_WAYPOINT)')

        where:
        what                                         | family               | item                   | north | up
        'a copter 4 m short, no hold time'           | VehicleFamily.COPTER | waypoint(100, 30)      | 96    | 30
        'a plane inside its WP_RADIUS (p1 no hold)'  | VehicleFamily.PLANE  | waypoint(1000, 100, 60) | 920  | 100
    }

    def "a long leg is no stall: progress of a metre or more restarts the clock, a hover's wander does not"() {
        given:
        def w = watch(VehicleFamily.COPTER, waypoint(5000, 30))

        expect: '5 km at 5 m/s: 1000 s without a warning'
        (0..1000).every { t -> w.look(at(VehicleFamily.COPTER, t * 5, 30, t), 1, true, t * S) == StallWatch.Notice.NONE }

        and: 'wandering half a metre back and forth is no progress'
        def stuck = watch(VehicleFamily.COPTER, waypoint(500, 30))
        (0..20).each { t -> stuck.look(at(VehicleFamily.COPTER, 100 + (t % 2) * 0.5, 30, t), 1, true, t * S) }
        stuck.look(at(VehicleFamily.COPTER, 100.5, 30, 21), 1, true, 21 * S).warning != null
    }

    @Unroll
    def "no stall: #what"() {
        given:
        def w = watch(family, item)

        expect: 'ten minutes at the same place'
        (0..600).every { t -> w.look(at(family, north, up, t), 1, true, t * S) == StallWatch.Notice.NONE }

        where:
        what                                                      | family               | item                                                                                                    | north | up
        'a copter holding 5 minutes at its waypoint'              | VehicleFamily.COPTER | waypoint(100, 30, 300)                                                                                  | 101   | 30
        'a copter circling a loiter item of 30 m radius'          | VehicleFamily.COPTER | MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, HOME.displace(100, 0, -30), 3, 0, 30, 0)            | 130   | 30
        'a plane circling its loiter at WP_LOITER_RAD'            | VehicleFamily.PLANE  | MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, HOME.displace(1000, 0, -100), 0, 0, 0, 0)           | 1060  | 100
        'a rover waiting at a NAV_DELAY'                          | VehicleFamily.ROVER  | MissionItem.command(1, MAV_CMD.MAV_CMD_NAV_DELAY, 120, -1, -1, -1)                                      | 50    | 0
        'a rover holding at its waypoint'                         | VehicleFamily.ROVER  | waypoint(50, 0, 60)                                                                                     | 49    | 0
        'a copter hovering at a loiter-time item'                 | VehicleFamily.COPTER | MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_LOITER_TIME, HOME.displace(100, 0, -30), 600, 0, 0, 0)            | 100   | 30
        'a sub holding a minute at its depth'                     | VehicleFamily.SUB    | waypoint(40, -10, 60)                                                                                   | 40    | -10
        'an item at no place (a waypoint at 0, 0: where it is)'  | VehicleFamily.COPTER | new MissionItem(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0, 0, 0, 0, 30, true) | 0 | 30
    }

    def "a plane's climb in a loiter to altitude is progress, though it circles"() {
        given: 'circling at 60 m from the centre, climbing 2 m/s from 100 m to 400 m'
        def w = watch(VehicleFamily.PLANE, MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, HOME.displace(1000, 0, -400), 0, 0, 0, 0))

        expect:
        (0..150).every { t -> w.look(at(VehicleFamily.PLANE, 1060, 100 + 2 * t, t), 1, true, t * S) == StallWatch.Notice.NONE }
    }

    def "a sub's slow dive is progress: 0.1 m/s toward a depth of 30 m"() {
        given:
        def w = watch(VehicleFamily.SUB, new MissionItem(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                0, 0, 0, 0, MissionItem.degE7(HOME.latitudeDegrees()), MissionItem.degE7(HOME.longitudeDegrees()), -30, true))

        expect:
        (0..290).every { t -> w.look(at(VehicleFamily.SUB, 0, -0.1 * t, t), 1, true, t * S) == StallWatch.Notice.NONE }
    }

    def "a copter's take-off is judged by its height: climbing is progress, stuck on the ground is a stall"() {
        given:
        def takeoff = new MissionItem(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0, 0, 0, 0, 30, true)
        def climbing = watch(VehicleFamily.COPTER, takeoff)
        def stuck = watch(VehicleFamily.COPTER, takeoff)

        expect:
        (0..25).every { t -> climbing.look(at(VehicleFamily.COPTER, 0, t, t), 1, true, t * S) == StallWatch.Notice.NONE }
        (0..20).every { t -> stuck.look(at(VehicleFamily.COPTER, 0, 0, t), 1, true, t * S) == StallWatch.Notice.NONE }
        stuck.look(at(VehicleFamily.COPTER, 0, 0, 21), 1, true, 21 * S).warning.contains('30 m from it')
    }

    def "held by someone else, or out of AUTO, the clock does not run; back in AUTO it starts again"() {
        given:
        def w = watch(VehicleFamily.COPTER, waypoint(500, 30))
        def s = at(VehicleFamily.COPTER, 300, 30)

        expect:
        (0..100).every { t -> w.look(fresh(s, t), 1, false, t * S) == StallWatch.Notice.NONE }
        (101..120).every { t -> w.look(fresh(s, t), 1, true, t * S) == StallWatch.Notice.NONE }
        w.look(fresh(s, 122), 1, true, 122 * S).warning != null
    }

    def "a new item starts the clock again; no position (GPS lost) is no stall"() {
        given:
        def w = watch(VehicleFamily.COPTER, waypoint(500, 30))
        def s = at(VehicleFamily.COPTER, 300, 30)

        expect:
        (0..19).every { t -> w.look(fresh(s, t), 1, true, t * S) == StallWatch.Notice.NONE }
        w.look(fresh(s, 20), 0, true, 20 * S) == StallWatch.Notice.NONE
        w.look(VehicleState.initial(VehicleFamily.COPTER), 1, true, 30 * S) == StallWatch.Notice.NONE
        (31..50).every { t -> w.look(fresh(s, t), 1, true, t * S) == StallWatch.Notice.NONE }
    }
}
