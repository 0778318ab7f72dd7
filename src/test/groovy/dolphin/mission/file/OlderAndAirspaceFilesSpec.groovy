package dolphin.mission.file

import dolphin.mission.model.Fence
import dolphin.mission.model.FenceRegion
import dolphin.mission.model.MissionItem
import dolphin.mission.model.RallyPoints
import dolphin.mission.model.VehicleProfile
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_TYPE
import dolphin.core.Position
import groovy.json.JsonSlurper
import spock.lang.Specification

/**
 * Geofences and rally points in plans and QGC WPL files, and what QGroundControl resolves when it
 * loads a plan (doJumpId, altitudes above terrain, its older files), on small texts made here.
 */
class OlderAndAirspaceFilesSpec extends Specification {

    static final Position HOME = Position.fromDegrees(-35.3632621, 149.1652374, 584)

    static Fence fence() {
        Fence.of([
                new FenceRegion.Polygon(true, [HOME.displace(-500, -500, 0), HOME.displace(-500, 500, 0),
                                               HOME.displace(500, 500, 0), HOME.displace(500, -500, 0)]),
                new FenceRegion.Circle(false, HOME.displace(200, 0, 0), 50.5),
                new FenceRegion.Polygon(false, [HOME.displace(-100, -100, 0), HOME.displace(-100, -50, 0),
                                                HOME.displace(-50, -75, 0)]),
        ], Position.fromDegrees(-35.3632621, 149.1652374, 30), MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT)
    }

    def "a fence built from regions has QGroundControl's items: polygons, then circles, then the return point"() {
        when:
        List<MissionItem> items = fence().items()

        then:
        items*.command() == [MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION] * 4 +
                [MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION] * 3 +
                [MAV_CMD.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION, MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT]
        items*.seq() == (0..8).toList()
        items[0..6]*.param1() == [4f] * 4 + [3f] * 3
        items[7].param1() == 50.5f
        items[8].frame() == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
        items[8].z() == 30f
        items.every { !it.autocontinue() }
        fence().describe() == '3 regions (inclusion polygon of 4 vertices, exclusion polygon of 3 vertices, exclusion circle of 50.5 m), return point'
    }

    def "a position breaks the fence outside its inclusion polygon or inside an exclusion region"() {
        expect:
        fence().breachedBy(HOME.displace(dn, de, 0)).map { it.describe() }.orElse('none') == breach

        where:
        dn   | de   | breach
        0    | 0    | 'none'
        400  | 400  | 'none'
        600  | 0    | 'inclusion polygon of 4 vertices'
        0    | -501 | 'inclusion polygon of 4 vertices'
        200  | 30   | 'exclusion circle of 50.5 m'
        200  | 51   | 'none'
        -90  | -75  | 'exclusion polygon of 3 vertices'
    }

    def "a plan keeps its geoFence and rallyPoints, written as QGroundControl writes them and read back the same"() {
        given:
        RallyPoints rally = RallyPoints.at([HOME.displace(100, 100, -40.4), HOME.displace(-100, 100, -60)])
        MissionFile file = MissionFile.of([MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0)])
                .withFence(fence()).withRally(rally)

        when:
        String text = PlanFile.write(file)
        Map json = new JsonSlurper().parseText(text) as Map
        MissionFile back = PlanFile.readFile(text)

        then: 'the JSON has QGroundControl keys and versions, heights above home'
        json.geoFence.version == 2
        json.geoFence.polygons*.inclusion == [true, false]
        json.geoFence.polygons*.version == [1, 1]
        json.geoFence.polygons[0].polygon.size() == 4
        json.geoFence.circles == [[version: 1, inclusion: false, circle: [center: json.geoFence.circles[0].circle.center, radius: 50.5]]]
        json.geoFence.breachReturn == [-35.3632621, 149.1652374, 30]
        json.rallyPoints.version == 2
        json.rallyPoints.points*.getAt(2) == [40, 60] // rounded to whole metres above mean sea level, written above home

        and: 'read back: the same regions, rally points above home'
        back.fence().regions().size() == 3
        back.fence().items() == fence().items()
        back.rally().items()*.frame() == [MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT] * 2
        back.rally().items()*.z() == [40f, 60f]
        back.rally().items()*.x() == rally.items()*.x()
    }

    def "version 1 fences and rally points are ignored, as QGroundControl does; other versions are refused"() {
        expect:
        PlanFile.readFile(plan('"geoFence": {"version": 1, "polygon": [[1, 2]]}, "rallyPoints": {"version": 1, "points": [[1, 2, 3]]}')).fence().isEmpty()

        when:
        PlanFile.readFile(plan(extra))

        then:
        IllegalArgumentException e = thrown()
        e.message.contains(message)

        where:
        extra                                                                           | message
        '"geoFence": {"version": 3, "polygons": [], "circles": []}'                     | 'geoFence.version 3 is not one QGroundControl reads (2; version 1 is ignored)'
        '"rallyPoints": {"version": 4, "points": []}'                                   | 'rallyPoints.version 4 is not one QGroundControl reads'
        '"geoFence": {"version": 2, "polygons": [{"version": 1, "inclusion": true, "polygon": [[1, 2], [1, 3]]}], "circles": []}' | 'geoFence.polygons[0].polygon: a fence polygon needs at least 3 vertices, found 2'
        '"geoFence": {"version": 2, "polygons": [], "circles": [{"version": 1, "inclusion": true, "circle": {"center": [1, 2], "radius": 0}}]}' | "geoFence.circles[0].circle.radius: a fence circle's radius is above 0 m, found 0"
        '"geoFence": {"version": 2, "polygons": [{"version": 2, "inclusion": true, "polygon": []}], "circles": []}' | 'geoFence.polygons[0].version 2 is not one QGroundControl reads (1)'
        '"geoFence": {"version": 2, "polygons": [{"version": 1, "polygon": [[1, 2], [1, 3], [2, 2]]}], "circles": []}' | 'geoFence.polygons[0].inclusion: expected true or false, found nothing'
        '"rallyPoints": {"version": 2, "points": [[95, 2, 3]]}'                         | 'rallyPoints.points[0][0]: 95 is out of range for a latitude (-90 to 90)'
        '"rallyPoints": {"version": 2, "points": [[5, 2, 40000]]}'                      | "rallyPoints.points[0]: rally item 0: height 40000 m is out of ArduPilot's range for rally points"
    }

    def "a DO_JUMP's param1 is its target's doJumpId in a plan, its item number once read"() {
        given:
        String text = plan(null, [
                item(16, 20, 'doJumpId": 10'),
                item(16, 20, 'doJumpId": 20'),
                '{"type": "SimpleItem", "command": 177, "frame": 2, "params": [20, 3, 0, 0, 0, 0, 0], "autoContinue": true, "doJumpId": 30}',
        ])

        when:
        List<MissionItem> items = PlanFile.read(text)

        then:
        items[3].command() == MAV_CMD.MAV_CMD_DO_JUMP
        items[3].param1() == 2f
        items[3].param2() == 3f

        and: 'written back with doJumpId = item number, it reads the same'
        PlanFile.read(PlanFile.write(items)) == items
    }

    def "an altitude QGroundControl was to calculate above terrain flies above terrain"() {
        when:
        List<MissionItem> items = PlanFile.read(plan(null, [
                '{"type": "SimpleItem", "command": 16, "frame": 0, "params": [0, 0, 0, null, 47.6, -122.04, null], "autoContinue": true, "AltitudeMode": 3, "Altitude": 80, "AMSLAltAboveTerrain": null}',
                '{"type": "SimpleItem", "command": 16, "frame": 0, "params": [0, 0, 0, null, 47.6, -122.04, 159.26], "autoContinue": true, "AltitudeMode": 3, "Altitude": 80, "AMSLAltAboveTerrain": 159.26}',
        ]))

        then: 'without the calculated altitude: 80 m above terrain; with it: as calculated'
        items[1].frame() == MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT
        items[1].z() == 80f
        items[2].frame() == MAV_FRAME.MAV_FRAME_GLOBAL_INT
        items[2].z() == 159.26f
    }

    def "QGroundControl's older files: items with a coordinate and four params, .mission of version 2 and of version 1.0"() {
        when:
        MissionFile sectioned = PlanFile.readFile(plan(null, [
                '{"type": "SimpleItem", "command": 22, "frame": 3, "coordinate": [47.63311996, -122.090763, 20], "params": [0, 0, 0, null], "autoContinue": true, "doJumpId": 1}']))
        MissionFile v2 = PlanFile.readFile('''{"fileType": "Mission", "version": 2, "groundStation": "QGroundControl",
                "firmwareType": 3, "vehicleType": 1, "cruiseSpeed": 22, "hoverSpeed": 4, "plannedHomePosition": [47.6, -122.09, 20],
                "items": [{"type": "SimpleItem", "command": 16, "frame": 3, "params": [0, 0, 0, 0, 47.61, -122.08, 100], "autoContinue": true, "doJumpId": 1}]}''')
        MissionFile v1 = PlanFile.readFile('''{"MAV_AUTOPILOT": 3, "groundStation": "QGroundControl", "version": "1.0",
                "plannedHomePosition": {"autoContinue": true, "command": 16, "coordinate": [34.577822, -112.469101, 584.380005], "frame": 0, "id": 0, "param1": 0, "param2": 0, "param3": 0, "param4": 0, "type": "missionItem"},
                "items": [{"autoContinue": true, "command": 22, "coordinate": [0, 0, 30], "frame": 2, "id": 1, "param1": 20, "param2": 0, "param3": 0, "param4": 0, "type": "missionItem"},
                          {"autoContinue": false, "command": 177, "coordinate": [0, 0, 0], "frame": 2, "id": 2, "param1": 1, "param2": 4, "param3": 0, "param4": 0, "type": "missionItem"}]}''')

        then:
        sectioned.mission()[1].x() == 476331200
        sectioned.mission()[1].z() == 20f
        sectioned.mission()[1].param4().isNaN()
        v2.vehicle() == new VehicleProfile(MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA, MAV_TYPE.MAV_TYPE_FIXED_WING, 22, 4)
        v2.mission()[1].z() == 100f
        v1.mission()[0].x() == 345778220
        v1.mission()[0].z() == 584.380005f
        v1.mission()[1].param1() == 20f
        v1.mission()[2].param1() == 1f // DO_JUMP to id 1: item 1
        !v1.mission()[2].autocontinue()
    }

    def "export keeps the vehicle the plan was made for"() {
        given:
        MissionFile plane = PlanFile.readFile(plan('"x": 0', []).replace('"vehicleType": 2', '"vehicleType": 1')
                .replace('"cruiseSpeed": 15', '"cruiseSpeed": 25'))

        expect:
        plane.vehicle().vehicleType() == MAV_TYPE.MAV_TYPE_FIXED_WING
        new JsonSlurper().parseText(PlanFile.write(plane)).mission.subMap('vehicleType', 'cruiseSpeed', 'firmwareType') ==
                [vehicleType: 1, cruiseSpeed: 25, firmwareType: 3]
    }

    def "a QGC WPL file of fence commands is a fence; of rally points, rally points; written back the same"() {
        given:
        String fenceText = WaypointsFile.writeItems(fence().items())
        String rallyText = WaypointsFile.writeItems(RallyPoints.at([HOME.displace(0, 100, -10)]).items())

        expect:
        fenceText.readLines()[1].startsWith('0\t0\t0\t5001\t4\t')
        MissionFile.read(fenceText).fence() == fence()
        !MissionFile.read(fenceText).hasMission()
        MissionFile.read(rallyText).rally().points()*.hae() == [594d]
        WaypointsFile.writeItems(MissionFile.read(fenceText).fence().items()) == fenceText
    }

    def "MAVProxy's legacy fence and rally files become today's items"() {
        when:
        Fence f = MissionFile.read('-35.361359\t149.162872\n-35.362522\t149.161926\n-35.362072\t149.164459\n' +
                '-35.360195\t149.163742\n-35.362522\t149.161926\n').fence()
        RallyPoints r = MissionFile.read('RALLY 40.071553\t-105.229401\t12.500000\t40.000000\t0.000000\t0\n').rally()

        then:
        f.returnPoint().get().latitudeDegrees() == -35.361359d
        f.regions() == [new FenceRegion.Polygon(true, f.regions()[0].vertices())]
        f.regions()[0].vertices().size() == 3
        r.items() == [new MissionItem(0, MAV_CMD.MAV_CMD_NAV_RALLY_POINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                0, 0, 0, 0, 400715530, -1052294010, 12.5f, false)]
    }

    def "QGC WPL 120 has no home line: item 0 is a placeholder and DO_JUMP targets move by one"() {
        when:
        List<MissionItem> items = MissionFile.read('QGC WPL 120\n0\t1\t3\t16\t3\t0\t0\t0\t-22.002177\t-47.932794\t13\t1\n' +
                '1\t0\t3\t177\t0\t2\t0\t0\t0\t0\t0\t1\n').mission()

        then:
        items.size() == 3
        items[0].x() == 0 && items[0].y() == 0
        items[1].x() == -220021770
        items[2].command() == MAV_CMD.MAV_CMD_DO_JUMP
        items[2].param1() == 1f
    }

    def "bad text files are refused in one line naming the line"() {
        when:
        MissionFile.read(text)

        then:
        IllegalArgumentException e = thrown()
        e.message.contains(message)
        !e.message.contains('\n')

        where:
        text                                                                                   | message
        'QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t1\t2\t3\t1\n1\t0\t0\t5001\t3\t0\t0\t0\t1\t2\t0\t0\n' | "line 3: NAV_FENCE_POLYGON_VERTEX_INCLUSION in a mission: a QGC WPL 110 file holds a mission, a fence or rally points"
        'QGC WPL 110\n0\t0\t0\t5001\t3\t0\t0\t0\t1\t2\t0\t0\n1\t0\t0\t5001\t3\t0\t0\t0\t1\t3\t0\t0\n' | 'line 3: fence item 1: the polygon that starts at item 0 has 2 of its 3 vertices: the fence ends before its last vertex'
        'QGC WPL 110\n0\t0\t0\t5001\t2\t0\t0\t0\t1\t2\t0\t0\n'                                    | "line 2: fence item 0: a polygon vertex's param1 is the polygon's vertex count, at least 3; found 2"
        'QGC WPL 110\n0\t0\t0\t5004\t0\t0\t0\t0\t1\t2\t0\t0\n'                                    | "line 2: fence item 0: NAV_FENCE_CIRCLE_EXCLUSION's param1 is its radius in metres, above 0; found 0"
        'QGC WPL 110\n0\t0\t0\t5000\t0\t0\t0\t0\t1\t2\t0\t0\n1\t0\t0\t5000\t0\t0\t0\t0\t1\t2\t0\t0\n' | 'line 3: fence item 1: a second NAV_FENCE_RETURN_POINT'
        'QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t95.5\t2\t3\t1\n'                                 | 'line 2: 95.5 is out of range for a latitude (-90 to 90)'
        '1.5\t2.5\n1\t2\n1\t3\n2\t2\n1\t2.5\n'                                                  | "line 5: the last point must repeat the polygon's first vertex (line 2) to close it"
        '1.5\t2.5\n1\t2\n1\t3\n1\t2\n'                                                          | 'at least 5 points, found 4'
        '1.5\t2.5\n1\t2 3\n'                                                                    | "line 2: a fence point line is 'lat lon', found 3 fields"
        'RALLY 1 2 3 4 5\n'                                                                     | "line 1: a rally line is 'RALLY lat lon alt break_alt land_dir flags', found 6 fields"
        'RALLY 1 2 3 4 5 x\n'                                                                   | "line 1: 'x' is not an integer"
        'QGC WPL 130\n'                                                                         | "not a QGC WPL 110 file: the first line must be 'QGC WPL 110', found 'QGC WPL 130'"
    }

    static String item(int command, float alt, String extra) {
        '{"type": "SimpleItem", "command": ' + command + ', "frame": 3, "params": [0, 0, 0, 0, 47.6, -122.09, ' + alt +
                '], "autoContinue": true, "' + extra + '}'
    }

    static String plan(String extra, List<String> items = []) {
        '{"fileType": "Plan", "version": 1, "groundStation": "QGroundControl", ' + (extra ? extra + ', ' : '') +
                '"mission": {"version": 2, "firmwareType": 3, "vehicleType": 2, "cruiseSpeed": 15, "hoverSpeed": 5, ' +
                '"plannedHomePosition": [-35.3632621, 149.1652374, 584], "items": [' + items.join(', ') + ']}}'
    }
}
