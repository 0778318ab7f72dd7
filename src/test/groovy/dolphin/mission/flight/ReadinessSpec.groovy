package dolphin.mission.flight

import com.MAVLink.common.msg_sys_status
import com.MAVLink.enums.MAV_SYS_STATUS_SENSOR
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.mavlink.Autopilot
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import spock.lang.Specification

/** What a vehicle lacks before it can take a mission (docs/mavlink.md, "Readiness"). */
class ReadinessSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final int PREARM = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK

    static VehicleState vehicle(Map m) {
        def hb = new msg_heartbeat()
        hb.base_mode = (short) (m.armed ? 129 : 1)
        def s = VehicleState.initial(VehicleFamily.COPTER).withHeartbeat(hb, 0)
        if (m.position) {
            s = s.withPosition(HOME, 0, Double.NaN, 0)
        }
        if (m.home) {
            s = s.withHome(HOME)
        }
        if (m.prearm != null) {
            def status = new msg_sys_status()
            status.onboard_control_sensors_present = PREARM
            status.onboard_control_sensors_enabled = PREARM
            status.onboard_control_sensors_health = m.prearm ? PREARM : 0
            s = s.withSystemStatus(status, 0)
        }
        if (m.ekf != null) {
            s = s.withEkfFlags(m.ekf as int)
        }
        (m.texts ?: []).each { s = s.withStatusText(it as String) }
        s
    }

    def "#what"() {
        expect:
        Readiness.missing(vehicle(state), needsHome) == Optional.ofNullable(missing)

        where:
        what                                                   | state                                                        | needsHome || missing
        'a vehicle booting: no position estimate yet'          | [prearm: false]                                              | true      || 'no position estimate yet'
        'its PreArm text is quoted when it sent one'           | [prearm: false, texts: ['PreArm: Need Position Estimate', 'GPS 1: detected u-blox']] | true || 'PreArm: Need Position Estimate'
        'a position but no home, when the mission needs it'    | [position: true, prearm: true]                               | true      || 'no home position yet'
        'no home is fine when the mission names its own'       | [position: true, prearm: true]                               | false     || null
        'a position, but the EKF has no absolute one yet (ArduRover sends GPS early)' | [position: true, home: true, prearm: true, ekf: 167] | true || 'no position estimate yet (EKF: no absolute horizontal position)'
        'the EKF in constant-position mode'                    | [position: true, home: true, prearm: true, ekf: 831 | 128]  | true      || 'no position estimate yet (EKF: no absolute horizontal position)'
        'the EKF using GPS'                                    | [position: true, home: true, prearm: true, ekf: 831]         | true      || null
        'pre-arm checks failing while disarmed'                | [position: true, home: true, prearm: false, texts: ['PreArm: Gyros inconsistent']] | true || 'PreArm: Gyros inconsistent'
        'pre-arm checks failing, no text yet'                  | [position: true, home: true, prearm: false]                  | true      || 'pre-arm checks failing'
        'armed and flying: the pre-arm sensor does not matter' | [armed: true, position: true, home: true, prearm: false]     | true      || null
        'ready'                                                | [position: true, home: true, prearm: true]                   | true      || null
        'no SYS_STATUS pre-arm sensor at all (not ArduPilot)'  | [position: true, home: true]                                 | true      || null
    }

    /** PX4's SYS_STATUS: the pre-arm bit in health only, set while it could arm in its mode; no bit in present or enabled. */
    static VehicleState px4(boolean canArm, List<String> texts = []) {
        def status = new msg_sys_status()
        status.onboard_control_sensors_health = canArm ? PREARM : 0
        def s = VehicleState.initial(Autopilot.PX4, VehicleFamily.COPTER).withHeartbeat(new msg_heartbeat(), 0)
                .withPosition(HOME, 0, Double.NaN, 0).withHome(HOME).withSystemStatus(status, 0)
        texts.each { s = s.withStatusText(it) }
        s
    }

    def "a PX4 vehicle is ready once the pre-arm bit is healthy; its 'Preflight Fail' text is quoted while not; ArduPilot's PreArm texts are not its"() {
        expect:
        Readiness.missing(px4(false, ['Preflight Fail: No valid data from Baro 0', 'PreArm: not PX4']), true).get() ==
                'Preflight Fail: No valid data from Baro 0'
        Readiness.missing(px4(false), true).get() == 'pre-arm checks failing'
        Readiness.missing(px4(true), true).empty
    }
}
