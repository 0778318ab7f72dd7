package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import dolphin.mission.model.MissionItem
import spock.lang.Specification
import spock.lang.Unroll

/**
 * The faults that end a flight, on a clock that is a number, and what must not raise them: a
 * copter landing at its end, a take-off from the ground, a rover (always on the ground), a warning,
 * frames reordered on the link.
 */
class FlightAlarmsSpec extends Specification {

    static final long S = 1_000_000_000L
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final int ON_GROUND = MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND
    static final int IN_AIR = MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR

    VehicleWords words = new VehicleWords()

    /** Home, take-off, two waypoints, a landing. */
    FlightAlarms alarms(VehicleFamily family) {
        def at = { int seq, int cmd, double north, double up -> MissionItem.at(seq, cmd, HOME.displace(north, 0, -up), 0, 0, 0, 0) }
        def items = [at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0, 0), at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 20),
                     at(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 20), at(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 200, 20),
                     at(4, MAV_CMD.MAV_CMD_NAV_LAND, 200, 0)]
        new FlightAlarms(FlightRules.of(family), new ItemNames(items), '1', words, 0, 0)
    }

    static VehicleState state(VehicleFamily family, boolean armed, int landed, double up) {
        def hb = new msg_heartbeat()
        hb.base_mode = (short) ((armed ? 128 : 0) | 1)
        hb.custom_mode = dolphin.mavlink.Autopilot.ARDUPILOT.modes(family).number('AUTO').asLong
        VehicleState.initial(family).withHeartbeat(hb, 0).withExtendedState(landed, 0)
                .withPosition(HOME.displace(100, 0, -up), up, Double.NaN, 0)
    }

    def "an emergency text fails the flight 2 s after it, quoting it with the warnings around it, not the chatter"() {
        given:
        def a = alarms(VehicleFamily.COPTER)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_INFO, 'SIM Hit ground at 13.8 m/s', 9 * S)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_WARNING, 'EKF primary changed:1', 9 * S)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_EMERGENCY, 'Potential Thrust Loss (2)', 10 * S)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_EMERGENCY, 'Potential Thrust Loss (2)', 11 * S)
        def s = state(VehicleFamily.COPTER, true, ON_GROUND, 0)

        expect:
        a.judge(s, 2, false, 10 * S).empty
        a.judge(s, 2, false, 12 * S).get() == "vehicle 1 reported 'EKF primary changed:1', 'Potential Thrust Loss (2)' during item 2 of 4" +
                ' (NAV_WAYPOINT): armed, AUTO, landed state ON_GROUND, 0.0 m above home'
    }

    def "ArduRover's 'Internal Errors 0x20000000' (CRITICAL) as its mission starts is no fault; a fault after it still is"() {
        given:
        def a = alarms(VehicleFamily.ROVER)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_INFO, 'Mission: 1 WP', 1 * S)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, 'Internal Errors 0x20000000', 1 * S)
        def s = state(VehicleFamily.ROVER, true, MAV_LANDED_STATE.MAV_LANDED_STATE_UNDEFINED, 0)

        expect: 'a minute of driving with it said'
        (1..60).every { t -> a.judge(s, 2, false, t * S).empty }

        when: 'the GPS is lost later'
        words.heard(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, 'EKF variance', 61 * S)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, 'EKF failsafe', 61 * S)

        then:
        a.judge(s, 3, false, 62 * S).empty
        a.judge(s, 3, false, 63 * S).get().startsWith("vehicle 1 reported 'EKF variance', 'EKF failsafe' during item 3 of 4")
    }

    def "texts from before the flight (a PreArm while it waited) do not count"() {
        given:
        def a = new FlightAlarms(FlightRules.of(VehicleFamily.COPTER), new ItemNames([MissionItem.command(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0, 0, 0, 0),
                MissionItem.command(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0, 0, 0, 0)]), '1', words, 5 * S, 0)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, 'PreArm: Need Position Estimate', 4 * S)

        expect:
        a.judge(state(VehicleFamily.COPTER, true, IN_AIR, 20), 1, false, 60 * S).empty
    }

    @Unroll
    def "no alarm: #what"() {
        given:
        def a = alarms(family)
        words.heard(MAV_SEVERITY.MAV_SEVERITY_WARNING, 'EKF primary changed:1', 1 * S)

        expect:
        steps.every { List step -> a.judge(state(family, step[1] as boolean, step[2] as int, step[3] as double), step[0] as int, false,
                (step[4] as long) * S).empty }

        where:
        what                                                | family               | steps
        'a copter on the ground at its take-off'            | VehicleFamily.COPTER | [[1, true, ON_GROUND, 0, 0], [1, true, ON_GROUND, 0, 5], [1, true, IN_AIR, 3, 6]]
        'a copter landing at its end, armed on the ground'  | VehicleFamily.COPTER | [[2, true, IN_AIR, 20, 0], [4, true, IN_AIR, 5, 10], [4, true, ON_GROUND, 0, 12], [4, true, ON_GROUND, 0, 20]]
        'a rover, always on the ground'                     | VehicleFamily.ROVER  | [[2, true, ON_GROUND, 0, 0], [3, true, ON_GROUND, 0, 30]]
        'a plane on the runway before its take-off'         | VehicleFamily.PLANE  | [[1, true, ON_GROUND, 0, 0], [1, true, ON_GROUND, 0, 10], [2, true, IN_AIR, 40, 30]]
        'a landed state flickering for under 2 s'           | VehicleFamily.COPTER | [[2, true, IN_AIR, 20, 0], [2, true, ON_GROUND, 20, 10], [2, true, IN_AIR, 20, 11], [2, true, IN_AIR, 20, 20]]
    }

    def "a flying vehicle on the ground with items left, though no text says why"() {
        given:
        def a = alarms(VehicleFamily.COPTER)

        expect:
        a.judge(state(VehicleFamily.COPTER, true, IN_AIR, 20), 2, false, 0).empty
        a.judge(state(VehicleFamily.COPTER, true, ON_GROUND, 0), 2, false, 10 * S).empty
        a.judge(state(VehicleFamily.COPTER, true, ON_GROUND, 0), 2, false, 12 * S).get() ==
                'vehicle 1 is on the ground during item 2 of 4 (NAV_WAYPOINT) with items left: armed, AUTO, landed state ON_GROUND, 0.0 m above home'
    }

    def "on the ground while someone else holds it (a pilot landed it) is the takeover's business, not this rule's"() {
        given:
        def a = alarms(VehicleFamily.COPTER)
        a.judge(state(VehicleFamily.COPTER, true, IN_AIR, 20), 2, false, 0)

        expect:
        (1..60).every { t -> a.judge(state(VehicleFamily.COPTER, true, ON_GROUND, 0), 2, true, t * S).empty }
    }

    def "a disarm waits 2 s for the vehicle's words, and for its next position, up to 4 s"() {
        given:
        def a = alarms(VehicleFamily.COPTER)
        a.judge(state(VehicleFamily.COPTER, true, IN_AIR, 20), 2, false, 0)
        def down = state(VehicleFamily.COPTER, false, ON_GROUND, 0)
        def heard = down.withPosition(down.position(), 0, Double.NaN, 11 * S)

        expect: 'no position since the disarm at 10 s: waited for to 14 s'
        a.judge(down, 3, false, 10 * S).empty
        words.heard(MAV_SEVERITY.MAV_SEVERITY_WARNING, 'Disarming motors', 10 * S + 500_000_000)
        a.judge(down, 3, false, 12 * S).empty
        a.judge(down, 3, false, 14 * S).present

        and: 'with a position heard after the disarm, the error comes 2 s after it'
        def b = alarms(VehicleFamily.COPTER)
        b.judge(state(VehicleFamily.COPTER, true, IN_AIR, 20), 2, false, 0).empty
        b.judge(heard, 3, false, 10 * S).empty
        b.judge(heard, 3, false, 12 * S).get() == "vehicle 1 disarmed during item 3 of 4 (NAV_WAYPOINT), saying 'Disarming motors': disarmed, AUTO," +
                ' landed state ON_GROUND, 0.0 m above home'
    }

    def "a reboot seen as a disarm, then the time since boot going back when the streams are asked for again, is a reboot"() {
        given:
        def a = alarms(VehicleFamily.COPTER)
        def flying = state(VehicleFamily.COPTER, true, IN_AIR, 30).withBootTime(300_000)
        a.judge(flying, 2, false, 0)
        def rebooted = state(VehicleFamily.COPTER, false, IN_AIR, 30).withBootTime(300_000)

        expect:
        a.judge(rebooted, 2, false, 10 * S).empty
        a.judge(rebooted, 2, false, 13 * S).empty
        a.judge(rebooted.withBootTime(3_400), 2, false, 13500 * 1_000_000L).get().startsWith('vehicle 1 rebooted during item 2 of 4')
    }

    def "a reboot: time since boot going back by more than 5 s; frames reordered on the link are not one"() {
        given:
        def a = alarms(VehicleFamily.COPTER)
        def s = state(VehicleFamily.COPTER, true, IN_AIR, 20).withBootTime(300_000)

        expect:
        s.withBootTime(296_000).reboots() == 0
        a.judge(s.withBootTime(296_000), 2, false, S).empty
        s.withBootTime(1_200).reboots() == 1
        a.judge(s.withBootTime(1_200), 2, false, 2 * S).get().startsWith('vehicle 1 rebooted during item 2 of 4 (NAV_WAYPOINT): its time since boot went back to 1.2 s')
    }
}
