package dolphin.sim

import com.MAVLink.common.msg_fence_status
import com.MAVLink.common.msg_home_position
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_sys_status
import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.FENCE_BREACH
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SYS_STATUS_SENSOR
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.enums.ROVER_MODE
import com.MAVLink.standard.msg_global_position_int
import dolphin.mission.model.Fence
import dolphin.mission.model.FenceRegion
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import spock.lang.Specification

import static dolphin.sim.MissionProtocolSpec.rel
import static dolphin.sim.SimDriver.HOME

/**
 * One simulated vehicle on a fake clock, no sockets: what it does at boot, at the ground and at the
 * end of a rover's mission (docs/mavlink.md, "The simulated fleet and real ArduPilot").
 */
class SimVehicleSpec extends Specification {

    static final int PREARM = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK

    static SimDriver streaming(SimDriver d) {
        [msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS, msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT,
         msg_home_position.MAVLINK_MSG_ID_HOME_POSITION, msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT].each {
            assert d.command(MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL, [it, 1_000_000]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        }
        d
    }

    static double horizontal(a, b) {
        def ned = a.displacementTo(b)
        Math.hypot(ned[0], ned[1])
    }

    def "booting, a copter has no position estimate for its warm-up: zeros, no home, DO_SET_HOME FAILED, PreArm every 30 s"() {
        given:
        def d = streaming(new SimDriver(VehicleKind.COPTER, SimOptions.DEFAULT.withWarmup(41)))
        int from = d.mark()

        when: 'the first 40 s'
        d.run(40)

        then: 'zeros for a position, no home, pre-arm checks failing and saying why once, 15 s after boot'
        d.since(from, msg_global_position_int).size() in 39..41
        d.since(from, msg_global_position_int).every { it.lat == 0 && it.lon == 0 && it.alt == 0 }
        d.since(from, msg_home_position).empty
        d.since(from, msg_sys_status).every { (it.onboard_control_sensors_health & PREARM) == 0 }
        d.texts(from) == ['PreArm: Need Position Estimate']

        and: 'it refuses a home and arming, saying why'
        d.command(MAV_CMD.MAV_CMD_DO_SET_HOME, [0, 0, 0, 0, HOME.latitudeDegrees(), HOME.longitudeDegrees(), HOME.hae()]).result ==
                MAV_RESULT.MAV_RESULT_FAILED
        d.arm().result == MAV_RESULT.MAV_RESULT_FAILED
        d.texts(from).last() == 'PreArm: Need Position Estimate'

        when: 'the warm-up is over'
        int ready = d.mark()
        d.run(5)

        then: 'its position, its home, pre-arm passing; DO_SET_HOME and arming accepted'
        d.since(ready, msg_global_position_int).last().with { Math.abs(it.lat / 1e7 - HOME.latitudeDegrees()) < 1e-6 && it.alt == 820_000 }
        !d.since(ready, msg_home_position).empty
        (d.since(ready, msg_sys_status).last().onboard_control_sensors_health & PREARM) != 0
        d.command(MAV_CMD.MAV_CMD_DO_SET_HOME, [0, 0, 0, 0, HOME.latitudeDegrees(), HOME.longitudeDegrees(), HOME.hae()]).result ==
                MAV_RESULT.MAV_RESULT_ACCEPTED
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
    }

    def "DO_SET_HOME in a COMMAND_LONG: its float latitude and longitude times 1e7 in float, truncated, as ArduCopter's home in copter-ftp-fence"() {
        given:
        def d = new SimDriver(VehicleKind.COPTER)

        when: 'what dolphin sent for 40.444233, -7.375234 (floats 40.44423294..., -7.37523412...)'
        def ack = d.command(MAV_CMD.MAV_CMD_DO_SET_HOME, [0, 0, 0, 0, 40.444233, -7.375234, 820])

        then: 'not 404442329 and -73752341, the values in double'
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        with(d.vehicle.mission()[0]) {
            x() == 404442336
            y() == -73752344
            z() == 820f
        }
    }

    def "a disarmed copter that never settles repeats its PreArm text every 30 s"() {
        given:
        def d = new SimDriver(VehicleKind.COPTER, SimOptions.DEFAULT.withWarmup(1000))

        when:
        d.run(100)

        then: 'at 15, 45 and 75 s'
        d.texts() == ['PreArm: Need Position Estimate'] * 3
    }

    def "with its fence on, a copter leaving the fence says so, reports FENCE_STATUS and returns (RTL); off, it flies on"() {
        given: 'a 100 m square around home, and a mission whose second waypoint is 150 m north'
        def d = new SimDriver(VehicleKind.COPTER)
        Fence fence = Fence.of([new FenceRegion.Polygon(true, [HOME.displace(-100, -100, 0), HOME.displace(-100, 100, 0),
                                                               HOME.displace(100, 100, 0), HOME.displace(100, -100, 0)])],
                null, MissionItem.GLOBAL_INT)
        assert d.upload(fence.items(), MissionType.FENCE) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        assert d.upload([MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                         rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10), rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 50, 0, 10),
                         rel(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 150, 0, 10)]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        if (enabled) {
            assert d.command(MAV_CMD.MAV_CMD_DO_FENCE_ENABLE, [1]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        }
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        d.arm()
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        assert d.command(MAV_CMD.MAV_CMD_MISSION_START).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        int from = d.mark()

        when:
        d.runUntil(120, 'the breach or the last waypoint') {
            d.texts(from).contains('Polygon fence breached') || d.since(from, msg_mission_item_reached)*.seq.contains(3)
        }

        then:
        d.vehicle.fence() == fence
        if (enabled) {
            assert d.vehicle.mode() == COPTER_MODE.COPTER_MODE_RTL
            assert horizontal(HOME, d.vehicle.position()) < 110 // turned back at the boundary
            def breach = d.since(from, msg_fence_status).find { it.breach_status == 1 }
            assert breach.breach_count == 1 && breach.breach_type == FENCE_BREACH.FENCE_BREACH_BOUNDARY
        } else {
            assert d.vehicle.mode() == COPTER_MODE.COPTER_MODE_AUTO
            assert d.since(from, msg_fence_status).empty
            assert !d.texts(from).contains('Polygon fence breached')
        }

        where:
        enabled << [true, false]
    }

    def "a copter flying a waypoint below the ground stops where it touches, says so and never goes lower"() {
        given:
        def d = new SimDriver(VehicleKind.COPTER)
        def waypoint = rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 0, -5)
        assert d.upload([MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                         rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10), waypoint]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        d.arm()
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        assert d.command(MAV_CMD.MAV_CMD_MISSION_START).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        int from = d.mark()
        double lowest = Double.MAX_VALUE

        when:
        d.runUntil(60, 'ground contact') {
            lowest = Math.min(lowest, d.vehicle.position().hae())
            d.texts(from).any { it.startsWith('SIM Hit ground') }
        }
        def touched = d.vehicle.position()
        60.times {
            d.run(0.5)
            lowest = Math.min(lowest, d.vehicle.position().hae())
        }

        then: 'on the ground, short of the waypoint, and there it stays, armed, the waypoint never reached'
        lowest >= HOME.hae()
        d.vehicle.position().hae() == HOME.hae()
        horizontal(touched, d.vehicle.position()) < 0.01
        horizontal(touched, HOME.displace(100, 0, 0)) > 10
        d.vehicle.armed()
        !(d.since(from, msg_mission_item_reached)*.seq).contains(2)
        d.texts(from).count { it.startsWith('SIM Hit ground') } == 1
    }

    def "a long leg at one height keeps that height: over 2 km the Earth's curvature is no descent"() {
        given:
        def d = new SimDriver(VehicleKind.COPTER)
        assert d.upload([MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                         rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 30), rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0, 2000, 30)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        d.arm()
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        d.command(MAV_CMD.MAV_CMD_MISSION_START)
        int from = d.mark()
        d.runUntil(30, 'the take-off') { d.since(from, msg_mission_item_reached)*.seq.contains(1) }
        double lowest = Double.MAX_VALUE

        when:
        d.runUntil(300, 'the waypoint 2 km away') {
            lowest = Math.min(lowest, d.vehicle.position().hae())
            d.since(from, msg_mission_item_reached)*.seq.contains(2)
        }

        then:
        lowest > HOME.hae() + 29.9
        !d.texts(from).any { it.startsWith('SIM Hit ground') }
        horizontal(d.vehicle.position(), HOME.displace(0, 2000, 0)) <= 1
    }

    def "a rover arms in MANUAL, drives its mission in AUTO, and holds in AUTO at the end: COMPLETE"() {
        given:
        def d = streaming(new SimDriver(VehicleKind.parse('ardurover')))
        assert d.upload([MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                         rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 20, 0, 0, 0, 50), rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 20, 20, 0)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        int from = d.mark()

        when:
        assert d.vehicle.mode() == ROVER_MODE.ROVER_MODE_MANUAL
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        assert d.setMode(ROVER_MODE.ROVER_MODE_AUTO).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        long start = d.now
        d.runUntil(60, 'the mission COMPLETE') { d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE }
        double seconds = (d.now - start) / 1e9
        d.run(5)

        then: 'both waypoints reached in order (within WP_RADIUS 3 m: the 50 m param2 of the first does not count for a rover), no faster than WP_SPEED 5 m/s, on the ground all the way, and it stands at the last one, in AUTO, armed'
        d.since(from, msg_mission_item_reached)*.seq == [1, 2]
        seconds >= (40 - 3) / 5
        d.texts(from).contains('Mission Complete')
        horizontal(d.vehicle.position(), HOME.displace(20, 20, 0)) <= 3
        d.vehicle.position().hae() == HOME.hae()
        d.vehicle.mode() == ROVER_MODE.ROVER_MODE_AUTO
        d.vehicle.armed()
        d.since(from, msg_mission_current).last().mission_state == MISSION_STATE.MISSION_STATE_COMPLETE
    }
}
