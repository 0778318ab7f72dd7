package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import dolphin.mission.model.MissionItem
import java.time.Duration
import spock.lang.Specification
import spock.lang.Unroll

import static dolphin.mission.flight.Takeovers.Look.Hand.FAILED
import static dolphin.mission.flight.Takeovers.Look.Hand.FLYING
import static dolphin.mission.flight.Takeovers.Look.Hand.HANDED_BACK
import static dolphin.mission.flight.Takeovers.Look.Hand.LEFT
import static dolphin.mission.flight.Takeovers.Look.Hand.PAUSED
import static dolphin.mission.flight.Takeovers.Look.Hand.TAKEN_OVER

/**
 * A pilot's pause against an abort, per family, on a clock that is a number: the takeover modes
 * pause, any other mode fails quoting the vehicle's words, a failsafe's change of mode is no pause,
 * and a plane's own RTL at its last item is left to the mission's end.
 */
class TakeoversSpec extends Specification {

    static final long S = 1_000_000_000L
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    VehicleWords words = new VehicleWords()

    /** Home and four waypoints; the last navigation item is 4. */
    Takeovers takeovers(VehicleFamily family, Duration timeout = Duration.ofSeconds(120)) {
        def items = (0..4).collect { MissionItem.at(it, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME.displace(100 * it, 0, -30), 0, 0, 0, 0) }
        new Takeovers(FlightRules.of(family), new ItemNames(items), '1', words, 4, Duration.ofSeconds(3), timeout)
    }

    static VehicleState in(VehicleFamily family, String mode) {
        def hb = new msg_heartbeat()
        hb.base_mode = (short) 129
        hb.custom_mode = dolphin.mavlink.Autopilot.ARDUPILOT.modes(family).number(mode).asLong
        VehicleState.initial(family).withHeartbeat(hb, 0).withPosition(HOME.displace(100, 0, -30), 30, Double.NaN, 0)
    }

    @Unroll
    def "#family: #mode pauses the mission, reported 2 s after the change; AUTO again hands it back"() {
        given:
        def t = takeovers(family)
        t.look(in(family, 'AUTO'), true, 2, 0)

        expect:
        t.look(in(family, mode), false, 2, 10 * S).hand() == LEFT
        t.look(in(family, mode), false, 2, 11 * S).hand() == LEFT
        t.look(in(family, mode), false, 2, 12 * S) == new Takeovers.Look(TAKEN_OVER, "taken over: ${mode} during item 2 of 4 (NAV_WAYPOINT)")
        t.paused()
        t.look(in(family, mode), false, 2, 20 * S).hand() == PAUSED
        t.look(in(family, 'AUTO'), true, 2, 25 * S) == new Takeovers.Look(HANDED_BACK, 'back in AUTO after 15 s: item 2 of 4 (NAV_WAYPOINT)')
        !t.paused()

        where:
        family               | mode
        VehicleFamily.COPTER | 'LOITER'
        VehicleFamily.COPTER | 'BRAKE'
        VehicleFamily.COPTER | 'STABILIZE'
        VehicleFamily.PLANE  | 'LOITER'
        VehicleFamily.PLANE  | 'FLY_BY_WIRE_A'
        VehicleFamily.PLANE  | 'QLOITER'
        VehicleFamily.ROVER  | 'HOLD'
        VehicleFamily.ROVER  | 'MANUAL'
        VehicleFamily.SUB    | 'POSHOLD'
    }

    @Unroll
    def "#family: #mode ends the mission's purpose: an error 2 s after the change"() {
        given:
        def t = takeovers(family)
        t.look(in(family, 'AUTO'), true, 2, 0)

        expect:
        t.look(in(family, mode), false, 2, 10 * S).hand() == LEFT
        def failed = t.look(in(family, mode), false, 2, 12 * S)
        failed.hand() == FAILED
        failed.text().startsWith("vehicle 1 left AUTO for ${mode} during item 2 of 4 (NAV_WAYPOINT), before the mission ended: armed, ${mode}")

        where:
        family               | mode
        VehicleFamily.COPTER | 'RTL'
        VehicleFamily.COPTER | 'LAND'
        VehicleFamily.COPTER | 'SMART_RTL'
        VehicleFamily.PLANE  | 'RTL'
        VehicleFamily.PLANE  | 'QLAND'
        VehicleFamily.ROVER  | 'RTL'
        VehicleFamily.SUB    | 'SURFACE'
    }

    def "a failsafe that holds the vehicle (a rover's HOLD) is no pause: its words are quoted"() {
        given:
        def t = takeovers(VehicleFamily.ROVER)
        t.look(in(VehicleFamily.ROVER, 'AUTO'), true, 2, 0)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_WARNING, 'Failsafe: GCS', 10 * S)

        expect:
        t.look(in(VehicleFamily.ROVER, 'HOLD'), false, 2, 10 * S).hand() == LEFT
        t.look(in(VehicleFamily.ROVER, 'HOLD'), false, 2, 12 * S) == new Takeovers.Look(FAILED, "vehicle 1 left AUTO for HOLD during item 2"
                + " of 4 (NAV_WAYPOINT), before the mission ended, saying 'Failsafe: GCS': armed, HOLD, landed state UNDEFINED, 30.0 m above home")
    }

    def "the GPS failsafe's own words, sent a moment after its change to LAND, are quoted; chatter is not"() {
        given:
        def t = takeovers(VehicleFamily.COPTER)
        t.look(in(VehicleFamily.COPTER, 'AUTO'), true, 2, 0)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_INFO, 'EKF primary changed:1', 9 * S)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_WARNING, 'EKF variance', 9 * S)

        when:
        t.look(in(VehicleFamily.COPTER, 'LAND'), false, 2, 10 * S)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, 'EKF Failsafe: changed to Land Mode', 10 * S + 300_000_000)
        def failed = t.look(in(VehicleFamily.COPTER, 'LAND'), false, 2, 12 * S)

        then:
        failed.text() == "vehicle 1 left AUTO for LAND during item 2 of 4 (NAV_WAYPOINT), before the mission ended, saying 'EKF variance'," +
                " 'EKF Failsafe: changed to Land Mode': armed, LAND, landed state UNDEFINED, 30.0 m above home"
    }

    def "a plane's own RTL at its last item waits the grace for the mission's end; in mid-mission it does not"() {
        given:
        def last = takeovers(VehicleFamily.PLANE)
        def mid = takeovers(VehicleFamily.PLANE)
        [last, mid].each { it.look(in(VehicleFamily.PLANE, 'AUTO'), true, 2, 0) }

        expect:
        last.look(in(VehicleFamily.PLANE, 'RTL'), false, 4, 10 * S).hand() == LEFT
        last.look(in(VehicleFamily.PLANE, 'RTL'), false, 4, 13 * S).hand() == LEFT
        last.look(in(VehicleFamily.PLANE, 'RTL'), false, 4, 13 * S + 1).hand() == FAILED
        mid.look(in(VehicleFamily.PLANE, 'RTL'), false, 2, 10 * S).hand() == LEFT
        mid.look(in(VehicleFamily.PLANE, 'RTL'), false, 2, 12 * S).hand() == FAILED
    }

    def "a pause moves between takeover modes freely; the timeout counts from the first change"() {
        given:
        def t = takeovers(VehicleFamily.COPTER, Duration.ofSeconds(60))
        t.look(in(VehicleFamily.COPTER, 'AUTO'), true, 2, 0)
        t.look(in(VehicleFamily.COPTER, 'LOITER'), false, 2, 10 * S)
        t.look(in(VehicleFamily.COPTER, 'LOITER'), false, 2, 12 * S)

        expect:
        t.look(in(VehicleFamily.COPTER, 'POSHOLD'), false, 2, 30 * S).hand() == PAUSED
        t.look(in(VehicleFamily.COPTER, 'POSHOLD'), false, 2, 70 * S).hand() == PAUSED
        t.look(in(VehicleFamily.COPTER, 'POSHOLD'), false, 2, 71 * S).text().startsWith('vehicle 1 taken over: POSHOLD for 61 s during item 2 of 4')
    }

    def "before the vehicle was first seen in AUTO, its mode is none of this rule's business"() {
        given:
        def t = takeovers(VehicleFamily.COPTER)

        expect:
        t.look(in(VehicleFamily.COPTER, 'GUIDED'), false, 1, 0).hand() == FLYING
        t.look(in(VehicleFamily.COPTER, 'GUIDED'), false, 1, 60 * S).hand() == FLYING
    }
}
