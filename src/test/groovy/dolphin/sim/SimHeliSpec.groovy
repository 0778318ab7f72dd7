package dolphin.sim

import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_param_value
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mission.model.MissionItem
import spock.lang.Specification

/**
 * The simulated traditional helicopter on a fake clock, against what ArduCopter SITL did with
 * {@code --model heli} and copter-heli.parm: its heartbeat, its motor interlock (on at boot, arming
 * refused while it is on, switched by MAV_CMD_DO_AUX_FUNCTION), the rotor's run-up before AUTO, GUIDED
 * and MISSION_START, and the copter's mission once it has run up.
 */
class SimHeliSpec extends Specification {

    static final int RELATIVE = MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
    static final Position HOME = SimDriver.HOME
    static final int LOW = 0
    static final int MIDDLE = 1
    static final int HIGH = 2

    static MissionItem item(int seq, int command, double north, double east, double z) {
        def p = HOME.displace(north, east, 0)
        new MissionItem(seq, command, RELATIVE, 0, 0, 0, 0, MissionItem.degE7(p.latitudeDegrees()),
                MissionItem.degE7(p.longitudeDegrees()), (float) z, true)
    }

    /** The findings' heli mission: a take-off to 20 m, two waypoints, a landing at home. */
    static List<MissionItem> mission() {
        [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0), item(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 20),
         item(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 50, 0, 20), item(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 50, 50, 20),
         item(4, MAV_CMD.MAV_CMD_NAV_LAND, 0, 0, 0)]
    }

    static SimDriver heli() {
        def d = new SimDriver(VehicleKind.HELI)
        d.run(1)
        assert d.upload(mission()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d
    }

    static int interlock(SimDriver d, int position) {
        d.command(MAV_CMD.MAV_CMD_DO_AUX_FUNCTION, [HeliFirmware.MOTOR_INTERLOCK, position]).result
    }

    /** Armed in GUIDED with the interlock off, as SITL had to be, then the interlock on (HIGH). */
    static SimDriver armedRunningUp() {
        def d = heli()
        assert d.setMode(COPTER_MODE.COPTER_MODE_GUIDED).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert interlock(d, LOW) == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert interlock(d, HIGH) == MAV_RESULT.MAV_RESULT_ACCEPTED
        d
    }

    def "a helicopter says MAV_TYPE_HELICOPTER and is of the HELI family, which runs ArduCopter's modes"() {
        given:
        def d = heli()

        expect:
        with(d.since(0, msg_heartbeat).first()) {
            type == MAV_TYPE.MAV_TYPE_HELICOPTER
            custom_mode == COPTER_MODE.COPTER_MODE_STABILIZE
        }
        VehicleKind.HELI.family() == VehicleFamily.HELI
        VehicleKind.HELI.family().firmware() == VehicleFamily.COPTER
    }

    def "its interlock is on at boot (SITL's RC8 at 1500, MIDDLE): arming is refused until DO_AUX_FUNCTION sets it LOW"() {
        given:
        def d = heli()
        int from = d.mark()

        when:
        def refused = d.arm()
        def middle = interlock(d, MIDDLE)
        def stillRefused = d.arm()
        def low = interlock(d, LOW)
        def armed = d.arm()

        then:
        refused.result == MAV_RESULT.MAV_RESULT_FAILED
        middle == MAV_RESULT.MAV_RESULT_ACCEPTED
        stillRefused.result == MAV_RESULT.MAV_RESULT_FAILED
        d.since(from, msg_statustext).collect { [it.severity, it.text] }.take(2) ==
                [[MAV_SEVERITY.MAV_SEVERITY_CRITICAL as short, 'Arm: Motor Interlock Enabled']] * 2
        low == MAV_RESULT.MAV_RESULT_ACCEPTED
        armed.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.texts(from).last() == 'Arming motors'
    }

    def "armed, AUTO and MISSION_START are refused until the rotor has run up (ramp 1 s + runup 10 s after the interlock went HIGH)"() {
        given:
        def d = heli()
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        interlock(d, LOW)
        d.arm()
        int from = d.mark()

        when: 'before the interlock, and 10.9 s after it'
        def before = d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        def startBefore = d.command(MAV_CMD.MAV_CMD_MISSION_START)
        interlock(d, HIGH)
        d.run(10.9)
        def early = d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        int refusedTexts = d.mark()

        and: '11 s after it'
        d.run(0.15)
        def auto = d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        def start = d.command(MAV_CMD.MAV_CMD_MISSION_START)

        then:
        [before, startBefore, early]*.result == [MAV_RESULT.MAV_RESULT_FAILED] * 3
        d.since(from, msg_statustext).take(3).collect { [it.severity, it.text] } ==
                [[MAV_SEVERITY.MAV_SEVERITY_WARNING as short, 'Mode change to Auto failed: runup not complete']] * 3
        auto.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        start.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        !d.texts(refusedTexts).any { it.contains('runup') }
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_AUTO
    }

    def "the run-up does not refuse #mode, or any mode while disarmed"() {
        given:
        def d = heli()
        interlock(d, LOW)

        expect: 'disarmed: Copter::set_mode ignores the checks'
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED).result == MAV_RESULT.MAV_RESULT_ACCEPTED

        when:
        d.arm()

        then: 'armed: the manual-throttle modes'
        d.setMode(mode).result == MAV_RESULT.MAV_RESULT_ACCEPTED

        where:
        mode << [COPTER_MODE.COPTER_MODE_STABILIZE, COPTER_MODE.COPTER_MODE_ACRO]
    }

    def "armed, #mode is refused before the run-up with its own name: '#text'"() {
        given:
        def d = armedRunningUp()
        int from = d.mark()

        expect:
        d.setMode(mode).result == MAV_RESULT.MAV_RESULT_FAILED
        d.texts(from) == [text]

        where:
        mode                           || text
        COPTER_MODE.COPTER_MODE_LOITER || 'Mode change to Loiter failed: runup not complete'
        COPTER_MODE.COPTER_MODE_RTL    || 'Mode change to RTL failed: runup not complete'
    }

    def "setting the interlock LOW starts the run-up over: 11 s from the next HIGH"() {
        given:
        def d = armedRunningUp()
        d.run(8)

        when:
        interlock(d, LOW)
        interlock(d, HIGH)
        d.run(8)
        def early = d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        d.run(3.1)
        def late = d.setMode(COPTER_MODE.COPTER_MODE_AUTO)

        then:
        early.result == MAV_RESULT.MAV_RESULT_FAILED
        late.result == MAV_RESULT.MAV_RESULT_ACCEPTED
    }

    def "the interlock set HIGH while disarmed counts only once armed: arming is refused, and nothing has run up"() {
        given:
        def d = heli()
        interlock(d, HIGH)
        d.run(20)

        expect:
        d.arm().result == MAV_RESULT.MAV_RESULT_FAILED
        interlock(d, LOW) == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO).result == MAV_RESULT.MAV_RESULT_FAILED
    }

    def "a reboot (--fault reboot) turns the interlock on again, as SITL's RC8 is read again: arming is refused until it is set LOW"() {
        given: 'armed with the interlock LOW, rebooted 5 s later'
        def d = new SimDriver(VehicleKind.HELI, SimOptions.DEFAULT.withFault(SimFault.parse('reboot@5')))
        d.run(1)
        interlock(d, LOW)
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.run(6)
        assert !d.vehicle.armed()
        int from = d.mark()

        expect:
        d.arm().result == MAV_RESULT.MAV_RESULT_FAILED
        d.texts(from) == ['Arm: Motor Interlock Enabled']
        interlock(d, LOW) == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
    }

    def "DO_AUX_FUNCTION of another function, or a switch position past HIGH, is UNSUPPORTED; a multicopter supports none"() {
        expect:
        new SimDriver(kind).command(MAV_CMD.MAV_CMD_DO_AUX_FUNCTION, [function, position]).result == MAV_RESULT.MAV_RESULT_UNSUPPORTED

        where:
        kind               | function                     | position
        VehicleKind.HELI   | 41                           | HIGH
        VehicleKind.HELI   | HeliFirmware.MOTOR_INTERLOCK | 3
        VehicleKind.COPTER | HeliFirmware.MOTOR_INTERLOCK | LOW
    }

    def "run up, it flies the copter's mission: take-off, waypoints, landing, the disarm, the mission started over at item 1"() {
        given:
        def d = armedRunningUp()
        d.run(11.5)

        when:
        assert d.setMode(COPTER_MODE.COPTER_MODE_AUTO).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert d.command(MAV_CMD.MAV_CMD_MISSION_START).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.runUntil(200, 'the disarm') { !d.vehicle.armed() }
        d.run(1)

        then:
        d.since(0, msg_mission_item_reached)*.seq == [1, 2, 3]
        d.texts().contains('Disarming motors')
        with(d.since(0, msg_mission_current).last()) {
            seq == 1
            mission_state == MISSION_STATE.MISSION_STATE_ACTIVE
        }
        d.vehicle.position().horizontalDistanceTo(HOME) < 1
    }

    def "it answers RC8_OPTION 32 and H_RSC_RUNUP_TIME 10"() {
        given:
        def d = heli()
        int from = d.mark()

        when:
        ['RC8_OPTION', 'H_RSC_RUNUP_TIME'].each {
            d.handle(SimQuadPlaneSpec.paramRead(it))
        }

        then:
        d.since(from, msg_param_value).collect { [it.getParam_Id(), it.param_value] } == [['RC8_OPTION', 32f], ['H_RSC_RUNUP_TIME', 10f]]
    }
}
