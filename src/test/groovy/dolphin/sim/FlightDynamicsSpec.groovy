package dolphin.sim

import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_RESULT
import dolphin.core.Position
import dolphin.mission.model.MissionItem
import spock.lang.Specification

import static dolphin.sim.MissionProtocolSpec.rel
import static dolphin.sim.SimDriver.HOME
import static dolphin.sim.SimVehicleSpec.horizontal

/**
 * How a simulated copter moves where SITL's timing shows in the recordings (docs/mavlink.md, "The
 * simulated fleet and real ArduPilot"): it waits for its motors before it lifts, gathers speed and
 * brakes at WPNAV_ACC, flies past a waypoint that another follows, and in RTL loiters over home
 * before its final descent.
 */
class FlightDynamicsSpec extends Specification {

    static final MissionItem HOME_ITEM = MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0)

    SimDriver d = new SimDriver(VehicleKind.COPTER)

    void start(List<MissionItem> items) {
        assert d.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        assert d.command(MAV_CMD.MAV_CMD_MISSION_START).result == MAV_RESULT.MAV_RESULT_ACCEPTED
    }

    /** The horizontal speed over the next tick, m/s. */
    double speed() {
        Position before = d.vehicle.position()
        d.tick()
        horizontal(before, d.vehicle.position()) / (SimDriver.TICK / 1e9)
    }

    def "after MISSION_START a copter stays on the ground while its motors spool up, then climbs"() {
        when:
        start([HOME_ITEM, rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10)])
        long t0 = d.now
        d.runUntil(10, 'lifting') { d.vehicle.position().hae() > HOME.hae() + 0.01 }

        then:
        Math.abs((d.now - t0) / 1e9 - CopterFirmware.SPOOL_UP) <= 0.2
        d.vehicle.landedState() == MAV_LANDED_STATE.MAV_LANDED_STATE_TAKEOFF
    }

    def "it flies past a waypoint another waypoint follows, slowed for the turn, and stops on the last"() {
        given:
        start([HOME_ITEM, rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10), rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 60, 0, 10),
               rel(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 60, 60, 10)])

        when:
        d.runUntil(60, 'at the corner') { d.vehicle.missionCurrent() == 3 }
        double corner = speed()
        d.runUntil(60, 'the last waypoint reached') { d.since(0, msg_mission_item_reached)*.seq.contains(3) }

        then: 'through the right-angled corner at about 2.5 m/s; stopped on the last point'
        corner > 2 && corner < 4
        horizontal(d.vehicle.position(), HOME.displace(60, 60, 0)) < 0.1
        speed() < 0.01
    }

    def "sent home at full speed it brakes (overshooting), returns, loiters 5 s over home, and only then lands"() {
        given:
        start([HOME_ITEM, rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 20), rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 300, 0, 20)])
        d.runUntil(120, '100 m north at full speed') { horizontal(d.vehicle.position(), HOME) > 100 }
        assert speed() > 9.9

        when:
        double breach = d.vehicle.position().displacementTo(HOME)[0] * -1
        d.setMode(COPTER_MODE.COPTER_MODE_RTL)
        double farthest = breach
        d.runUntil(60, 'over home') {
            farthest = Math.max(farthest, -d.vehicle.position().displacementTo(HOME)[0])
            horizontal(d.vehicle.position(), HOME) < 1 && speed() < 0.01
        }
        long over = d.now
        d.runUntil(10, 'landing') { d.vehicle.landedState() == MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING }
        double loiter = (d.now - over) / 1e9

        then: 'WPNAV_ACC 2.5 m/s² stops 10 m/s in 20 m; RTL_LOIT_TIME 5 s'
        farthest - breach > 18 && farthest - breach < 22
        loiter >= ReturnAndLand.LOITER_TIME - 0.1 && loiter < ReturnAndLand.LOITER_TIME + 0.2
        d.vehicle.position().hae() > HOME.hae() + 19
    }
}
