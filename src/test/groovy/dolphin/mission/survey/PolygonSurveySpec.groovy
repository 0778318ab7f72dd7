package dolphin.mission.survey

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.mission.model.MissionItem
import spock.lang.Specification

import static dolphin.mission.survey.SurveyFixtures.*
import static dolphin.mission.survey.TransectPoint.PointKind.*

/**
 * Polygon surveys worked out by hand from docs/qgc-surveys.md §2: on the 100 m square the grid
 * lines lie at x = cx - 1050 + 30k m, so a 30 m spacing gives transects at 20, 50 and 80 m east of
 * the west side, the first from north to south (lines run south to north and the first crossing,
 * of the north edge, comes first; the lawnmower reverses the second).
 */
class PolygonSurveySpec extends Specification {

    static final int WP = MAV_CMD.MAV_CMD_NAV_WAYPOINT, TRIG = MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST
    static final int SHOT = MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE
    static final PhotoGrid GRID = PhotoGrid.manual(50, 30, 25)

    static PolygonSurvey survey(Map o = [:]) {
        new PolygonSurvey('survey', o.polygon ?: SQUARE, o.grid ?: GRID, (o.angle ?: 0) as double,
                o.entry ?: EntryCorner.TOP_LEFT, (o.alternate ?: false) as boolean, o.options ?: TransectOptions.defaults())
    }

    def "a 100 m square at 30 m spacing: three transects 30 m apart, flown lawnmower-fashion with 10 m turnarounds"() {
        when:
        PolygonSurvey s = survey()
        List<List<Double>> path = s.path().collect { metres(it) }

        then:
        s.transects().size() == 3
        s.path()*.kind() == [TURNAROUND, ENTRY, EXIT, TURNAROUND] * 3
        [path, [[20, 10], [20, 0], [20, -100], [20, -110],
                [50, -110], [50, -100], [50, 0], [50, 10],
                [80, 10], [80, 0], [80, -100], [80, -110]]].transpose().every { a, b -> near(a, b) }
        Math.abs(s.coverage().pathLength() - (3 * 120 + 2 * 30)) < 0.01
        s.coverage().photos() == 17 // ceil(420 / 25): photos in the turnarounds too
        s.qgcType() == 'survey'
        s.getPosition() == null
    }

    def "the entry corner picks the first transect and its direction (#entry)"() {
        when:
        List<TransectPoint> path = survey(entry: entry).path()

        then:
        near(metres(path[1]), first)
        near(metres(path[2]), second)

        where:
        entry                     | first     | second
        EntryCorner.TOP_LEFT      | [20, 0]   | [20, -100]
        EntryCorner.TOP_RIGHT     | [80, 0]   | [80, -100]
        EntryCorner.BOTTOM_LEFT   | [20, -100] | [20, 0]
        EntryCorner.BOTTOM_RIGHT  | [80, -100] | [80, 0]
    }

    def "current items: a start at the first turnaround and at every entry, one stop at the end, float trigger distance"() {
        when:
        List<MissionItem> items = survey().items(5)
        List<MissionItem> wps = items.findAll { it.command() == WP }
        List<MissionItem> trigs = items.findAll { it.command() == TRIG }

        then:
        items*.command() == [WP, TRIG, WP, TRIG, WP, WP,
                             WP, WP, TRIG, WP, WP,
                             WP, WP, TRIG, WP, WP, TRIG]
        items*.seq() == (5..21).toList()
        wps.every { it.frame() == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT && it.z() == 50f && Float.isNaN(it.param4()) }
        trigs.every { it.frame() == MAV_FRAME.MAV_FRAME_MISSION }
        trigs.collect { [it.param1(), it.param2(), it.param3()] } == [[25f, 0f, 1f]] * 4 + [[0f, 0f, 1f]]
        items.size() == survey().messageCount()
    }

    def "legacy survey items without photos in turnarounds: start after each entry, stop with param3 0 after each exit"() {
        when:
        List<MissionItem> items = survey(options: TransectOptions.defaults().withTurnaround(0).withTriggerInTurnarounds(false)
                .withEmission(Emission.LEGACY_SURVEY)).items(1)

        then:
        items*.command() == [WP, TRIG, WP, TRIG] * 3
        items.findAll { it.command() == TRIG }.collect { [it.param1(), it.param3()] } == [[25f, 1f], [0f, 0f]] * 3
    }

    def "the altitude reference sets the waypoints' frame"() {
        expect:
        survey(options: TransectOptions.defaults().withHeight(height)).items(1).findAll { it.command() == WP }*.frame().unique() == [frame]

        where:
        height                          | frame
        HeightReference.ABOVE_HOME      | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
        HeightReference.ABOVE_SEA_LEVEL | MAV_FRAME.MAV_FRAME_GLOBAL_INT
        HeightReference.ABOVE_TERRAIN   | MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT
    }

    def "hover and capture: a stop and a photo every 25 m, the last at the exit"() {
        when:
        PolygonSurvey s = survey(options: TransectOptions.defaults().withTurnaround(0).withHoverAndCapture(true))
        List<MissionItem> items = s.items(1)

        then:
        s.transects()[0]*.kind() == [ENTRY, HOVER, HOVER, HOVER, HOVER, EXIT]
        near(metres(s.transects()[0][2]), [20, -50])
        items*.command() == [WP, SHOT] * 18
        items.findAll { it.command() == WP }*.param1().unique() == [4f]
        s.coverage().photos() == 18
    }

    def "alternate transects: 0, 2, 4, then 5, 3, 1 back"() {
        when: 'an 18 m spacing gives six transects at 8, 26, 44, 62, 80 and 98 m'
        PolygonSurvey s = survey(grid: PhotoGrid.manual(50, 18, 25), alternate: true)

        then:
        s.transects().collect { Math.round(metres(it[1])[0]) } == [8, 44, 80, 98, 62, 26]
    }

    def "refly at 90°: a second pass of east-west transects starting near where the first ended"() {
        when:
        PolygonSurvey s = survey(options: TransectOptions.defaults().withRefly90(true))
        List<List<TransectPoint>> second = s.transects().drop(3)
        List<Double> end = metres(s.transects()[2].last())

        then:
        s.transects().size() == 6
        second.every { Math.abs(metres(it[1])[1] - metres(it[2])[1]) < 0.01 }
        Math.hypot(metres(second[0][0])[0] - end[0], metres(second[0][0])[1] - end[1]) < 60
    }

    def "a concave U: each transect runs from its first to its last crossing, spanning the notch as QGC's do"() {
        when: 'transects run east-west'
        PolygonSurvey s = survey(polygon: U, grid: PhotoGrid.manual(50, 40, 25), angle: 90,
                options: TransectOptions.defaults().withTurnaround(0))
        List<List<List<Double>>> ends = s.transects().collect { t -> [metres(t[0]), metres(t[1])] }

        then:
        s.transects().size() == 7
        ends.every { Math.abs(Math.abs(it[0][0] - it[1][0]) - 300) < 0.01 }
        ends.count { it[0][1] > -200 } >= 4 // these cross the notch between x = 100 and 200
    }

    def "fewer than two grid lines hit a small polygon: one transect through the middle"() {
        when:
        PolygonSurvey s = survey(polygon: outline([[0, 0], [20, 0], [20, -20], [0, -20]]))

        then:
        s.transects().size() == 1
        near(metres(s.transects()[0][1]), [10, 0])
        near(metres(s.transects()[0][2]), [10, -20])
    }

    def "fewest passes: a strip 100 m wide and 2 km long north to south is flown north to south"() {
        given:
        def strip = outline([[0, 0], [100, 0], [100, -2000], [0, -2000]])

        expect:
        PolygonSurvey.fewestPassesAngle(strip, 30) == 0
        survey(polygon: strip, angle: 0).transects().size() < survey(polygon: strip, angle: 90).transects().size()
    }

    def "footprints: a GoPro Hero 4 at 100 m, one 207 x 155 m rectangle every 31.06 m from each entry"() {
        given:
        PhotoGrid gopro = PhotoGrid.atAltitude(Cameras.named('GoPro Hero 4').get(), true, 100, 80, 80)
        PolygonSurvey s = survey(grid: gopro, options: TransectOptions.defaults().withTurnaround(0).withTriggerInTurnarounds(false))
        List<List<dolphin.core.Position>> prints = s.footprints()
        List<List<Double>> first = prints[0].collect { metres(it) }
        List<Double> centre = [first.sum { it[0] } / 4, first.sum { it[1] } / 4]

        expect:
        prints.size() == s.transects().size() * 4 // floor(100 / 31.06) + 1 photos per transect
        near(centre, metres(s.transects()[0][0]), 0.01)
        Math.abs(Math.hypot(first[0][0] - first[1][0], first[0][1] - first[1][1]) - gopro.footprintSide()) < 0.01
        Math.abs(Math.hypot(first[1][0] - first[2][0], first[1][1] - first[2][1]) - gopro.footprintFrontal()) < 0.01
        s.coverage().gsd() == gopro.gsd()
        survey().footprints().isEmpty() // manual: no camera, no footprint
    }
}
