package dolphin.mission.file

import dolphin.mission.model.MissionItem
import dolphin.mission.model.VehicleProfile
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_TYPE
import groovy.json.JsonSlurper
import spock.lang.Specification

import static MissionFileFixtures.*

class PlanFileSpec extends Specification {

    static Map json(String text) {
        new JsonSlurper().parseText(text) as Map
    }

    def "export then import gives the same items, NaN parameters included"() {
        when:
        def back = PlanFile.read(PlanFile.write(items))

        then:
        back == items

        where:
        items << [mission(), withoutNegativeZero(extremes()), random(11, 40), random(12, 40), random(13, 200)]
    }

    def "extreme floats survive; -0 is written as -0.0 but reads back as 0 (JSON readers have no -0)"() {
        when:
        def text = PlanFile.write(extremes())
        def back = PlanFile.read(text)[1]

        then:
        json(text).mission.items[0].params[0..3] == [0, 1e-7, 3.4028235e38, 1.4e-45]
        text.contains('-0.0,')
        Float.floatToRawIntBits(back.param1()) == 0
        back.param2() == 1e-7f
        back.param3() == Float.MAX_VALUE
        back.param4() == Float.MIN_VALUE
        !back.autocontinue()
    }

    static List<MissionItem> withoutNegativeZero(List<MissionItem> items) {
        Closure<Float> z = { float f -> f == 0 ? 0f : f }
        items.collect { new MissionItem(it.seq(), it.command(), it.frame(), z(it.param1()), z(it.param2()), z(it.param3()),
                z(it.param4()), it.x(), it.y(), z(it.z()), it.autocontinue()) }
    }

    def "the plan's skeleton: fileType, versions, ArduPilot, speeds, empty geofence and rally points"() {
        when:
        def plan = json(PlanFile.write(mission()))

        then:
        plan.fileType == 'Plan'
        plan.version == 1
        plan.groundStation == 'Dolphin'
        plan.mission.version == 2
        plan.mission.firmwareType == 3
        plan.mission.vehicleType == MAV_TYPE.MAV_TYPE_QUADROTOR
        plan.mission.cruiseSpeed == 15
        plan.mission.hoverSpeed == 5
        plan.geoFence == [version: 2, polygons: [], circles: []]
        plan.rallyPoints == [version: 2, points: []]
    }

    def "the vehicle type can be given"() {
        expect:
        json(PlanFile.write(MissionFile.of(mission()).withVehicle(VehicleProfile.ardupilot(MAV_TYPE.MAV_TYPE_FIXED_WING))))
                .mission.vehicleType == MAV_TYPE.MAV_TYPE_FIXED_WING
    }

    def "the home is plannedHomePosition [lat, lon, alt] and the items start at seq 1"() {
        when:
        def plan = json(PlanFile.write(mission()))

        then:
        plan.mission.plannedHomePosition == [40.444233, -7.375234, 820]
        plan.mission.items.size() == mission().size() - 1
        plan.mission.items*.doJumpId == (1..<mission().size()).toList()
    }

    def "a SimpleItem: type, command, float frame, 7 params with x and y in degrees, NaN as null"() {
        when:
        def items = json(PlanFile.write(mission())).mission.items

        then:
        items[0] == [type: 'SimpleItem', command: 22, frame: 0, params: [15, 0, 0, null, 40.444233, -7.375234, 1200],
                     autoContinue: true, doJumpId: 1]
        items[2] == [type: 'SimpleItem', command: 178, frame: 2, params: [0, 12.5, -1, 0, 0, 0, 0],
                     autoContinue: true, doJumpId: 3]
        and: 'the float 0.1 is written as 0.1, not 0.10000000149011612'
        PlanFile.write(mission()).contains('0.1,')
        !PlanFile.write(mission()).contains('0.1000000')
    }

    def "NaN altitude and NaN parameters are null in the file and NaN again after import"() {
        given:
        def items = [new MissionItem(0, 16, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 0, 0, 0, 0, 10, 20, 30, true),
                     new MissionItem(1, 17, MAV_FRAME.MAV_FRAME_GLOBAL_INT, Float.NaN, Float.NaN, Float.NaN, Float.NaN, 10, 20, Float.NaN, true)]

        when:
        def text = PlanFile.write(items)

        then:
        json(text).mission.items[0].params == [null, null, null, null, 0.000001, 0.000002, null]
        PlanFile.read(text)[1] == items[1]
    }

    def "the output is deterministic and pretty-printed"() {
        expect:
        PlanFile.write(mission()) == PlanFile.write(mission())
        PlanFile.write(mission()).readLines().size() > 20
    }

    def "import flattens a survey ComplexItem into its pre-expanded items"() {
        when:
        def items = PlanFile.read(QGC_SURVEY_PLAN)

        then:
        items*.seq() == [0, 1, 2, 3, 4, 5]
        items[0] == new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 0, 0, 0, 0,
                473977420, 85455940, 488f, true)
        items[1].command() == MAV_CMD.MAV_CMD_NAV_TAKEOFF
        items[1].frame() == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
        items[1].param4().isNaN()
        items[2..4]*.command() == [MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, MAV_CMD.MAV_CMD_NAV_WAYPOINT]
        items[2].x() == 473982510
        items[2].y() == 85448010
        items[4].x() == 473971230
        items[3].param1() == 25f
        items[5].command() == MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH
        items[5].frame() == MAV_FRAME.MAV_FRAME_MISSION
    }

    def "a text that is not a plan is rejected with the reason"() {
        when:
        PlanFile.read(text)

        then:
        def e = thrown(IllegalArgumentException)
        e.message.contains(reason)

        where:
        text                                                                                      | reason
        'QGC WPL 110\n'                                                                           | 'the text is not JSON'
        '[]'                                                                                      | 'the JSON is not an object'
        '{"fileType": "GeoFence"}'                                                                | '"fileType" must be "Plan", found GeoFence'
        '{"fileType": "Plan", "version": 1}'                                                      | 'mission: expected a JSON object, found nothing'
        '{"fileType": "Plan", "version": 1, "mission": {"version": 2, "items": []}}'              | 'mission.plannedHomePosition: expected a JSON array'
        '{"fileType": "Plan", "version": 1, "mission": {"version": 2, "plannedHomePosition": [1, 2], "items": []}}' | 'must be [lat, lon, alt]'
        '{"fileType": "Plan", "mission": {}}'                                                     | 'version: missing; QGroundControl plans are of version 1'
        '{"fileType": "Plan", "version": 42, "mission": {}}'                                      | 'version 42 is not one QGroundControl reads: its plans are of version 1'
        '{"fileType": "Plan", "version": 1, "mission": {"version": 7}}'                           | 'mission.version 7 is not one QGroundControl reads'
        '{"fileType": "Mission", "version": 3}'                                                   | 'version 3 is not one QGroundControl reads: its .mission files are of version 2'
        '{"MAV_AUTOPILOT": 3, "version": "2.0", "items": []}'                                     | 'version 2.0: QGroundControl\'s .mission files without fileType are of version 1.0'
        plan('{"type": "Thing"}')                                                                 | 'mission.items[0]: unknown item type "Thing"'
        plan('{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0], "autoContinue": true}') | 'mission.items[0].params must have 7 values, found 3'
        plan('{"type": "SimpleItem", "command": "WP", "frame": 3, "params": [0, 0, 0, 0, 0, 0, 0]}') | 'mission.items[0].command: expected an integer, found "WP"'
        plan('{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, "x", 0, 0, 0, 0]}') | 'mission.items[0].params[2]: expected a number or null, found "x"'
        plan('{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0, 91.5, 0, 0]}') | 'mission.items[0].params[4] (latitude): 91.5 is out of range for a latitude (-90 to 90)'
        plan('{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0, 0, -181, 0]}') | 'mission.items[0].params[5] (longitude): -181 is out of range for a longitude (-180 to 180)'
        plan('{"type": "SimpleItem", "command": 177, "frame": 2, "params": [9, 1, 0, 0, 0, 0, 0], "doJumpId": 1}') | 'mission.items[0]: DO_JUMP to doJumpId 9, which no item of the mission has'
        plan('{"type": "SimpleItem", "command": 16, "frame": 0, "params": [0, 0, 0, 0, 1, 2, null], "AltitudeMode": 3}') | 'mission.items[0]: the altitude is to be calculated above terrain, but the plan has neither'
        plan('{"type": "ComplexItem", "complexItemType": "fwLandingPattern"}')                     | "ComplexItem 'fwLandingPattern' has no TransectStyleComplexItem.Items"
        plan('{"type": "ComplexItem", "complexItemType": "survey", "version": 9}')                 | 'mission.items[0]: survey version 9 is not one QGroundControl reads (2 to 5)'
        plan('{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0], "coordinate": [1, 2]}') | 'an item with a coordinate [lat, lon, alt] has 4 params, found 4 params and 2 coordinate values'
        plan('{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0, 0, 0, 0], "autoContinue": "yes"}') | 'mission.items[0].autoContinue: expected true or false, found "yes"'
    }

    static String plan(String item) {
        '{"fileType": "Plan", "version": 1, "mission": {"version": 2, "plannedHomePosition": [1, 2, 3], "items": [' + item + ']}}'
    }

    /** A plan as QGroundControl 4 saves it: a take-off, a survey (ComplexItem), and RTL. */
    static final String QGC_SURVEY_PLAN = '''{
    "fileType": "Plan",
    "geoFence": {"circles": [], "polygons": [], "version": 2},
    "groundStation": "QGroundControl",
    "mission": {
        "cruiseSpeed": 15,
        "firmwareType": 3,
        "globalPlanAltitudeMode": 1,
        "hoverSpeed": 5,
        "items": [
            {
                "AMSLAltAboveTerrain": null,
                "Altitude": 50,
                "AltitudeMode": 1,
                "autoContinue": true,
                "command": 22,
                "doJumpId": 1,
                "frame": 3,
                "params": [0, 0, 0, null, 47.3977419, 8.5455938, 50],
                "type": "SimpleItem"
            },
            {
                "TransectStyleComplexItem": {
                    "CameraCalc": {"AdjustedFootprintFrontal": 25, "AdjustedFootprintSide": 25, "CameraName": "Manual (no camera specs)", "DistanceToSurface": 50, "DistanceToSurfaceRelative": true, "version": 1},
                    "CameraTriggerInTurnAround": true,
                    "FollowTerrain": false,
                    "HoverAndCapture": false,
                    "Items": [
                        {"autoContinue": true, "command": 16, "doJumpId": 2, "frame": 3, "params": [0, 0, 0, null, 47.398251, 8.544801, 50], "type": "SimpleItem"},
                        {"autoContinue": true, "command": 206, "doJumpId": 3, "frame": 2, "params": [25, 0, 1, 0, 0, 0, 0], "type": "SimpleItem"},
                        {"autoContinue": true, "command": 16, "doJumpId": 4, "frame": 3, "params": [0, 0, 0, null, 47.397123, 8.544801, 50], "type": "SimpleItem"}
                    ],
                    "Refly90Degrees": false,
                    "TurnAroundDistance": 10,
                    "VisualTransectPoints": [[47.398251, 8.544801], [47.397123, 8.544801]],
                    "version": 1
                },
                "angle": 0,
                "complexItemType": "survey",
                "entryLocation": 0,
                "flyAlternateTransects": false,
                "polygon": [[47.3983, 8.5447], [47.3983, 8.5460], [47.3970, 8.5460], [47.3970, 8.5447]],
                "splitConcavePolygons": false,
                "type": "ComplexItem",
                "version": 5
            },
            {
                "autoContinue": true,
                "command": 20,
                "doJumpId": 5,
                "frame": 2,
                "params": [0, 0, 0, 0, 0, 0, 0],
                "type": "SimpleItem"
            }
        ],
        "plannedHomePosition": [47.397742, 8.545594, 488],
        "vehicleType": 2,
        "version": 2
    },
    "rallyPoints": {"points": [], "version": 2},
    "version": 1
}
'''
}
