package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.core.Position
import dolphin.mission.model.MissionItem
import spock.lang.Specification

class FixedWingApproachSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    /** Home, a take-off, the entrance {@code south} metres south of home {@code up} metres above it, and a landing at home. */
    static List<MissionItem> landing(int entrance, double south, double up, float radius = 0, int landFrame = MissionItem.GLOBAL_INT) {
        MissionItem land = MissionItem.at(3, MAV_CMD.MAV_CMD_NAV_LAND, HOME, 0, 0, 0, 0)
        [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
         MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, HOME.atHeight(880), 0, 0, 0, 0),
         MissionItem.at(2, entrance, HOME.displace(-south, 0, 0).atHeight(HOME.hae() + up), 0, radius, 0, 0),
         new MissionItem(3, land.command(), landFrame, 0, 0, 0, 0, land.x(), land.y(), land.z(), true)]
    }

    def "a landing from a waypoint on a glide slope up to the vehicle's angle is flown; a steeper one is refused, saying how to fix it"() {
        expect:
        !FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 600, 30), 5).present
        !FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 340, 30), 5).present
        FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 30), 5).get() ==
                'PX4 refuses the approach to the landing at item 3 from item 2 (NAV_WAYPOINT): it comes down 30 m over 100 m,' +
                ' a glide slope of 16.7 degrees, steeper than the vehicle\'s 5.0 (FW_LND_ANG): start it at least 337 m out,' +
                ' or at most 8 m above the landing'

        and: 'the vehicle\'s own angle counts'
        !FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 30), 17).present
    }

    def "an entrance at or below the landing is refused"() {
        expect:
        FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 600, -5), 5).get()
                .endsWith('it must start above the landing, and starts 5 m below it')
    }

    def "from a loiter to altitude the approach is the tangent from its circle, and a landing inside the circle is refused"() {
        expect: 'a 400 m tangent from 500 m out on a 300 m circle: 60 m down is 8.5 degrees'
        FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, 500, 60, 300), 5).get().contains('down 60 m over 400 m')
        !FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, 600, 30, 80), 5).present
        FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, 60, 30, -80), 5).get()
                .endsWith('the landing is 60 m from the loiter\'s centre, inside its 80 m circle: land outside it')
    }

    def "a landing entered from another item with a position is refused; after a command without one, or from another height reference, PX4 is left to judge"() {
        expect:
        FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_LOITER_TIME, 600, 30), 5).get()
                .endsWith('a fixed-wing landing is entered from a waypoint or a loiter to altitude')
        !FixedWingApproach.refusal(landing(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 30, 0, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT), 5).present

        when: 'a speed change between the steep waypoint and the landing'
        def items = landing(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 30)
        items.add(3, MissionItem.command(3, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 0, 12, -1, 0))

        then:
        !FixedWingApproach.refusal(items, 5).present
    }

    def "a PX4 plane refuses a steep approach before the upload, with the vehicle's FW_LND_ANG or its default; a PX4 multicopter lands anyhow"() {
        given:
        def steep = landing(MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 30)
        def boarding = { Map<String, OptionalDouble> params -> new Boarding(null, [:], params) }

        when:
        Px4Rules.FIXED_WING.onBoard(steep, boarding([:]))

        then:
        def e = thrown(IllegalArgumentException)
        e.message.contains('steeper than the vehicle\'s 5.0')

        expect:
        Px4Rules.FIXED_WING.parameters() == ['FW_LND_ANG']
        Px4Rules.FIXED_WING.onBoard(steep, boarding([FW_LND_ANG: OptionalDouble.of(20)])).items().size() == 4
        Px4Rules.MULTICOPTER.onBoard(steep, boarding([:])).items().size() == 4
    }
}
