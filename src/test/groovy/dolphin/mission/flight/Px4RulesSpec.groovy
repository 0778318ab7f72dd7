package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.mavlink.Autopilot
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import dolphin.mission.model.MissionItem
import spock.lang.Specification

/** What PX4 flies and refuses before an upload (Px4Rules; docs/px4.md, "What PX4 flies"). */
class Px4RulesSpec extends Specification {

    static MissionItem item(int command, int frame = MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT) {
        new MissionItem(2, command, frame, 0, 0, 0, 0, 404442330, -73752340, 30, true)
    }

    def "a PX4 vehicle of family #family flies by #rules"() {
        expect:
        FlightRules.of(VehicleState.initial(Autopilot.PX4, family)) == rules
        FlightRules.of(VehicleState.initial(Autopilot.ARDUPILOT, family)) != rules

        where:
        family               || rules
        VehicleFamily.COPTER || Px4Rules.MULTICOPTER
        VehicleFamily.PLANE  || Px4Rules.FIXED_WING
        VehicleFamily.VTOL   || Px4Rules.VTOL
    }

    def "#name is refused: #why"() {
        expect:
        Px4Rules.MULTICOPTER.cannotFly(item).get() == why

        where:
        item                                                                              || why
        item(MAV_CMD.MAV_CMD_CONDITION_DELAY, MAV_FRAME.MAV_FRAME_MISSION)                || "PX4's missions do not fly this command: hold at a waypoint (its param1) or add a NAV_DELAY instead"
        item(MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT)                                         || "PX4's missions do not fly this command: use plain waypoints"
        item(MAV_CMD.MAV_CMD_DO_SET_SERVO, MAV_FRAME.MAV_FRAME_MISSION)                   || "PX4's missions do not fly this command: use DO_SET_ACTUATOR instead"
        item(MAV_CMD.MAV_CMD_DO_AUX_FUNCTION, MAV_FRAME.MAV_FRAME_MISSION)                || "PX4's missions do not fly this command"
        item(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT)    || 'PX4 takes no height above terrain in a mission: give the height above home or sea level'
        name = item.commandName()
    }

    def "what PX4 flies passes: #name; a plane refuses VTOL items, a VTOL does not"() {
        expect:
        !Px4Rules.MULTICOPTER.cannotFly(item).present
        !Px4Rules.VTOL.cannotFly(item).present
        Px4Rules.FIXED_WING.cannotFly(item).present == vtolItem

        where:
        item                                                                   || vtolItem
        item(MAV_CMD.MAV_CMD_NAV_WAYPOINT)                                     || false
        item(MAV_CMD.MAV_CMD_NAV_LOITER_TIME)                                  || false
        item(MAV_CMD.MAV_CMD_NAV_DELAY, MAV_FRAME.MAV_FRAME_MISSION)           || false
        item(MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, MAV_FRAME.MAV_FRAME_MISSION) || false
        item(MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF)                                 || true
        name = item.commandName()
    }
}
