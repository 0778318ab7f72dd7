package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import dolphin.mavlink.VehicleFamily
import spock.lang.Specification

/** How each family is armed, started and held, and which missions end on the ground (docs/mavlink.md). */
class FlightRulesSpec extends Specification {

    def "#family: arms in #armMode, MISSION_START #start, holds in #hold, lands after LAND #land and RTL #rtl"() {
        given:
        FlightRules rules = FlightRules.of(family)

        expect:
        rules.armMode().orElse('its mode') == armMode
        rules.needsMissionStart() == start
        rules.holdMode() == hold
        dolphin.mavlink.Autopilot.ARDUPILOT.modes(family).number(hold).present || family == VehicleFamily.OTHER
        dolphin.mavlink.Autopilot.ARDUPILOT.modes(family).number(rules.cutShortMode()).present || family == VehicleFamily.OTHER || family == VehicleFamily.SUB
        rules.landsAfter(MAV_CMD.MAV_CMD_NAV_LAND) == land
        rules.landsAfter(MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH) == rtl
        !rules.landsAfter(MAV_CMD.MAV_CMD_NAV_WAYPOINT)

        where:
        family               || armMode    | start | hold     | land  | rtl
        VehicleFamily.COPTER || 'GUIDED'   | true  | 'LOITER' | true  | true
        VehicleFamily.HELI   || 'GUIDED'   | true  | 'LOITER' | true  | true
        VehicleFamily.PLANE  || 'its mode' | false | 'LOITER' | true  | false
        VehicleFamily.VTOL   || 'AUTO'     | false | 'LOITER' | true  | false
        VehicleFamily.ROVER  || 'its mode' | false | 'HOLD'   | false | false
        VehicleFamily.OTHER  || 'its mode' | false | 'HOLD'   | false | false
    }
}
