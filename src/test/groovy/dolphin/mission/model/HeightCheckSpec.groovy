package dolphin.mission.model

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.core.Position
import spock.lang.Specification

/** No item but a landing lower than home + 2 m unless the mission allows it (docs/mission-commands.md, "Safe heights"). */
class HeightCheckSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    static MissionItem item(int command, int frame, double z) {
        new MissionItem(1, command, frame, 0, 0, 0, 0, 404442330, -73752340, (float) z, true)
    }

    static Mission raw(MissionItem... items) {
        RawItemPoint.mission('m', [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0)] + items.toList())
    }

    def "#what"() {
        expect:
        HeightCheck.firstUnsafe(raw(item(command, frame, z)), HOME).map { it.seq() }.orElse(null) == tooLow

        where:
        what                                            | command                             | frame                                      | z      || tooLow
        'a waypoint 2 m above home is fine'             | MAV_CMD.MAV_CMD_NAV_WAYPOINT        | MAV_FRAME.MAV_FRAME_GLOBAL_INT             | 822    || null
        'a waypoint 1.9 m above home is not'            | MAV_CMD.MAV_CMD_NAV_WAYPOINT        | MAV_FRAME.MAV_FRAME_GLOBAL_INT             | 821.9  || 1
        'a loiter at home height'                       | MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM    | MAV_FRAME.MAV_FRAME_GLOBAL_INT             | 820    || 1
        'a take-off to home height'                     | MAV_CMD.MAV_CMD_NAV_TAKEOFF         | MAV_FRAME.MAV_FRAME_GLOBAL_INT             | 820    || 1
        'relative frame: 1 m above home'                | MAV_CMD.MAV_CMD_NAV_WAYPOINT        | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT | 1     || 1
        'relative frame: 30 m above home'               | MAV_CMD.MAV_CMD_NAV_WAYPOINT        | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT    | 30     || null
        'a landing goes down to the ground'             | MAV_CMD.MAV_CMD_NAV_LAND            | MAV_FRAME.MAV_FRAME_GLOBAL_INT             | 820    || null
        'above terrain: the terrain is not known here'  | MAV_CMD.MAV_CMD_NAV_WAYPOINT        | MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT | 0      || null
        'a DO item has no height'                       | MAV_CMD.MAV_CMD_DO_CHANGE_SPEED     | MAV_FRAME.MAV_FRAME_MISSION                | 0      || null
    }

    def "the first item too low is named with its seq, word and command"() {
        given:
        Mission m = raw(item(MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 840),
                item(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 820.5),
                item(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 800))

        expect:
        HeightCheck.firstUnsafe(m, HOME).get().message() == "mission m: item 2 (item, NAV_WAYPOINT) is 0.5 m above home" +
                " (home at 820.0 m): lower than the 2 m clearance, into the ground or nearly; only landings go lower." +
                " Raise it, or write 'allowBelowHome true' in the mission if this is intended"
    }

    def "a mission that allows it, or a home not known yet, is not checked"() {
        given:
        Mission low = raw(item(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 700))
        Mission allowed = new Mission('m', HOME, low.commandList, true)

        expect:
        HeightCheck.firstUnsafe(low, HOME).present
        HeightCheck.firstUnsafe(allowed, HOME).empty
        HeightCheck.firstUnsafe(low, null).empty
    }
}
