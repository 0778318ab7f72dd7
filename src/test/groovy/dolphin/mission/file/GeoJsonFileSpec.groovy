package dolphin.mission.file

import dolphin.mission.model.MissionItem
import groovy.json.JsonSlurper
import spock.lang.Specification

import static MissionFileFixtures.*

class GeoJsonFileSpec extends Specification {

    static Map geo(List<MissionItem> items, String name = 'survey') {
        new JsonSlurper().parseText(GeoJsonFile.write(name, items)) as Map
    }

    def "a FeatureCollection named after the mission: a Point per positioned item, then the path"() {
        when:
        def g = geo(mission())

        then:
        g.type == 'FeatureCollection'
        g.name == 'survey'
        g.features*.type.every { it == 'Feature' }
        g.features*.geometry*.type == ['Point'] * 5 + ['LineString']
    }

    def "points are [lon, lat, alt] with seq, command name, frame and params (NaN as null)"() {
        when:
        def points = geo(mission()).features.findAll { it.geometry.type == 'Point' }

        then: 'the items without a position (DO_CHANGE_SPEED at 3, NAV_DELAY at 5) have no point'
        points*.properties*.seq == [0, 1, 2, 4, 6]
        points*.properties*.command == ['NAV_WAYPOINT', 'NAV_TAKEOFF', 'NAV_WAYPOINT', 'NAV_LOITER_TURNS', 'NAV_LAND']

        and:
        points[0].geometry.coordinates == [-7.375234, 40.444233, 820]
        points[0].properties == [seq: 0, command: 'NAV_WAYPOINT', frame: 'GLOBAL_INT', params: [0, 0, 0, 0], home: true]
        points[1].properties == [seq: 1, command: 'NAV_TAKEOFF', frame: 'GLOBAL_INT', params: [15, 0, 0, null]]
        points[3].geometry.coordinates == [151.2092955, -33.8688197, 55.25]
        points[3].properties.params == [3, 0, 0.1, 0]
    }

    def "the LineString is the flight path: the points' coordinates in mission order, from the home"() {
        when:
        def features = geo(mission()).features
        def line = features.find { it.geometry.type == 'LineString' }

        then:
        line.geometry.coordinates == features.findAll { it.geometry.type == 'Point' }*.geometry*.coordinates
        line.properties.name == 'survey'
    }

    def "items at latitude 0, longitude 0 or in a non-global frame are not points"() {
        given:
        def items = [MissionItem.at(0, 16, HOME, 0, 0, 0, 0),
                     new MissionItem(1, 20, MissionItem.GLOBAL_INT, 0, 0, 0, 0, 0, 0, 0, true),
                     new MissionItem(2, 16, MissionItem.MISSION, 0, 0, 0, 0, 5, 5, 0, true)]

        expect:
        !GeoJsonFile.hasPosition(items[1])
        !GeoJsonFile.hasPosition(items[2])
        geo(items).features*.geometry*.type == ['Point']
    }

    def "GeoJSON is export only"() {
        when:
        MissionFormat.GEOJSON.read('{}')

        then:
        thrown(UnsupportedOperationException)
        !MissionFormat.GEOJSON.canRead()
        MissionFormat.PLAN.canRead()
    }

    def "formats by name and extension"() {
        expect:
        MissionFormat.parse(name) == format
        format.extension() == extension

        where:
        name        | format                    | extension
        'plan'      | MissionFormat.PLAN        | '.plan'
        'WAYPOINTS' | MissionFormat.WAYPOINTS   | '.waypoints'
        'geojson'   | MissionFormat.GEOJSON     | '.geojson'
    }

    def "an unknown format name lists the known ones"() {
        when:
        MissionFormat.parse('kml')

        then:
        def e = thrown(IllegalArgumentException)
        e.message == "unknown format 'kml': expected one of plan, waypoints, geojson"
    }

    def "MissionFormat reads what it writes (plan and waypoints)"() {
        expect:
        format.read(format.write('m', mission())) == mission()

        where:
        format << [MissionFormat.PLAN, MissionFormat.WAYPOINTS]
    }

    def "a survey adds its outline with its numbers and its photo footprints as one MultiPolygon"() {
        given:
        def survey = PlanComplexItemsSpec.cameraSurvey()
        MissionFile f = PlanComplexItemsSpec.file(survey)

        when:
        def features = (new JsonSlurper().parseText(GeoJsonFile.write('survey', f)) as Map).features
        def outline = features.find { it.properties.kind == 'survey' }
        def footprints = features.find { it.properties.footprints }

        then:
        outline.geometry.type == 'Polygon'
        outline.geometry.coordinates[0].size() == 5
        outline.geometry.coordinates[0][0] == [-7.376, 40.445]
        outline.properties.word == 'survey'
        outline.properties.seq == 2
        outline.properties.photos == survey.coverage().photos()
        outline.properties.gsd == survey.coverage().gsd()
        outline.properties.spacing == survey.photoGrid().spacing()
        outline.properties.triggerDistance == survey.photoGrid().triggerDistance()

        and:
        footprints.geometry.type == 'MultiPolygon'
        footprints.geometry.coordinates.size() == survey.footprints().size()
        footprints.geometry.coordinates.every { it.size() == 1 && it[0].size() == 5 && it[0][0] == it[0][4] }
        footprints.properties == [footprints: 'survey', seq: 2, photos: survey.footprints().size()]
    }

    def "a corridor's outline is its path, a LineString; a manual survey has no footprints"() {
        when:
        def features = (new JsonSlurper().parseText(GeoJsonFile.write('c', PlanComplexItemsSpec.file(item))) as Map).features

        then:
        features.find { it.properties.kind == kind }.geometry.type == geometry
        features.find { it.properties.footprints } == null

        where:
        item                                 | kind           | geometry
        PlanComplexItemsSpec.manualSurvey()  | 'survey'       | 'Polygon'
        PlanComplexItemsSpec.corridor()      | 'CorridorScan' | 'LineString'
    }
}
