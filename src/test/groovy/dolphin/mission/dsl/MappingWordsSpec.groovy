package dolphin.mission.dsl

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.core.Position
import dolphin.dsl.ScriptError
import dolphin.mission.flight.MissionTask
import dolphin.mission.model.Mission
import dolphin.mission.model.MissionItem
import dolphin.mission.survey.MappingItem
import dolphin.mission.survey.PolygonSurvey
import dolphin.mission.survey.TransectPoint
import dolphin.platform.MAVLinkLanguage
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/**
 * The mapping words (docs/mission-commands.md, "Mapping") in scripts: worked examples whose numbers
 * are computed here by hand from the camera's formulas (docs/qgc-surveys.md, §1.2), and each mistake
 * a script error at its line. Geometry is measured with Position.displacementTo, independently of
 * the survey engine's projection.
 */
class MappingWordsSpec extends Specification {

    static final String FILE = 'mapping.dolphin'
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    /** A 200 m square north-east of home, as the script below writes it. */
    static final String SQUARE = '''
            homePos = location(40.444233, -7.375234, 820)
            corner = { double n, double e -> move(homePos) { north n; east e } }
    '''

    ScriptHarness h = new ScriptHarness(0)

    def setup() {
        h.engine.addExtension(new MAVLinkLanguage())
    }

    Mission mission(String name) {
        (h.engine.variable(name) as MissionTask).mission()
    }

    static double[] ned(double lat, double lon) {
        HOME.displacementTo(Position.fromDegrees(lat, lon, HOME.hae()))
    }

    def "a square with a named camera: lines north-south the camera's spacing apart, a photo every trigger distance"() {
        when:
        def r = h.run(SQUARE + '''
            m = mission {
                home homePos
                takeOff location(40.444233, -7.375234, 880)
                survey {
                    polygon corner(0, 0), corner(200, 0), corner(200, 200), corner(0, 200)
                    camera 'Sony a6000 16mm'
                    altitude 60
                    frontOverlap 75
                    sideOverlap 65
                    turnaround 0
                }
                returnHomeAndLand()
            }
        ''', FILE)
        Mission m = mission('m')
        PolygonSurvey s = m.commandList.find { it instanceof PolygonSurvey } as PolygonSurvey
        // G = 60 m x 23.5 mm x 100 / (6000 px x 16 mm); across: 6000 px x G / 100 x (1 - 0.65); along: 4000 px x G / 100 x (1 - 0.75)
        double gsd = 60 * 23.5 * 100 / (6000 * 16)
        double spacing = 6000 * gsd / 100 * 0.35
        double trigger = 4000 * gsd / 100 * 0.25
        List<TransectPoint> entries = s.path().findAll { it.kind() == TransectPoint.PointKind.ENTRY }
        List<Double> easts = entries.collect { ned(it.latitude(), it.longitude())[1] }
        List<MissionItem> items = m.items(null)
        List<MissionItem> trig = items.findAll { it.command() == MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST }

        then:
        r.outcome == COMPLETED
        Math.abs(s.coverage().gsd() - gsd) < 1e-9
        Math.abs(s.photoGrid().spacing() - spacing) < 1e-9
        Math.abs(s.photoGrid().triggerDistance() - trigger) < 1e-9
        // 200 m / 30.8 m: 6 or 7 lines, as QGroundControl's grid phase falls
        entries.size() in [Math.floor(200 / spacing) as int, Math.floor(200 / spacing) as int + 1]
        // QGroundControl lays the lines out on a sphere, measured here on WGS-84: east-west at 40° they are 0.3 % apart
        (1..<easts.size()).every { Math.abs(Math.abs(easts[it] - easts[it - 1]) - spacing) < spacing * 0.004 }
        easts.every { it >= -0.5 && it <= 200.5 }
        // every line runs from the south edge to the north edge, alternating
        s.path().findAll { it.kind() in [TransectPoint.PointKind.ENTRY, TransectPoint.PointKind.EXIT] }
                .every { double n = ned(it.latitude(), it.longitude())[0]; Math.abs(n) < 0.5 || Math.abs(n - 200) < 0.5 }
        // QGroundControl's current items: a waypoint at each end, triggering on at entry, off at exit (turnaround 0)
        trig.first().param1() == (float) trigger
        trig.first().param3() == 1f
        trig.last().param1() == 0f
        items.findAll { it.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT && it.frame() == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT }*.z
                .every { it == 60f }
    }

    def "a concave (U-shaped) field: a line that meets the notch flies across it, from the first edge to the last, as QGroundControl"() {
        when: 'a U open to the north: two 60 m wide arms around an 80 m wide notch, flown in east-west lines'
        def r = h.run(SQUARE + '''
            m = mission {
                home homePos
                survey {
                    polygon corner(0, 0), corner(0, 200), corner(200, 200), corner(200, 140), corner(60, 140), corner(60, 60), corner(200, 60), corner(200, 0)
                    altitude 50
                    spacing 30
                    triggerDistance 20
                    angle 90
                }
            }
        ''', FILE)
        PolygonSurvey s = mission('m').commandList.find { it instanceof PolygonSurvey } as PolygonSurvey
        List<List<double[]>> lines = s.path().findAll { it.kind() in [TransectPoint.PointKind.ENTRY, TransectPoint.PointKind.EXIT] }
                .collect { ned(it.latitude(), it.longitude()) }.collate(2)

        then:
        r.outcome == COMPLETED
        // east-west lines north of 60 m meet the west arm, the notch, the east arm: each runs from the west edge to the
        // east edge, across the notch
        lines.any { l -> l.every { it[0] > 61 && it[0] < 199 } && l*.getAt(1).min() < 1 && l*.getAt(1).max() > 199 }
    }

    def "fewestPasses picks the angle along a long thin field"() {
        when: 'a field 400 m north-east by 60 m'
        def r = h.run(SQUARE + '''
            m = mission {
                home homePos
                survey {
                    polygon corner(0, 0), corner(283, 283), corner(240, 325), corner(-42, 42)
                    altitude 50
                    spacing 20
                    fewestPasses()
                }
            }
        ''', FILE)
        PolygonSurvey s = mission('m').commandList.find { it instanceof PolygonSurvey } as PolygonSurvey

        then: 'across the field: three lines of 20 m cover its 60 m; north-south lines would need 17'
        r.outcome == COMPLETED
        s.angle() >= 40 && s.angle() <= 50
        s.path().count { it.kind() == TransectPoint.PointKind.ENTRY } == 3
    }

    def "a corridor along a road and a structure scan around a building"() {
        when:
        def r = h.run(SQUARE + '''
            m = mission {
                home homePos
                corridorScan {
                    path corner(0, 0), corner(300, 0), corner(400, 100)
                    width 60
                    altitude 40
                    spacing 25
                    triggerDistance 15
                }
                structureScan {
                    polygon corner(0, 0), corner(0, 20), corner(30, 20), corner(30, 0)
                    height 25
                    distance 10
                    layerHeight 5
                    triggerDistance 4
                }
            }
        ''', FILE)
        List<MappingItem> mapping = mission('m').commandList.findAll { it instanceof MappingItem }

        then:
        r.outcome == COMPLETED
        mapping*.qgcType() == ['CorridorScan', 'StructureScan']
        // ceil(60 / 25) = 3 lines along the road
        mapping[0].path().count { it.kind() == TransectPoint.PointKind.ENTRY } == 3
        // 25 m / 5 m = 5 layers of (4 + 3) items, plus 4: docs/qgc-surveys.md §3.2
        mapping[1].items(1).size() == (4 + 3) * 5 + 4
    }

    def "after a survey, relative commands start from its last waypoint (home known: heights above home are known)"() {
        when:
        def r = h.run(SQUARE + '''
            m = mission {
                home homePos
                survey {
                    polygon corner(0, 0), corner(100, 0), corner(100, 100), corner(0, 100)
                    altitude 50
                    spacing 30
                }
                move 10, 0
            }
        ''', FILE)
        List<MissionItem> items = mission('m').items(null)

        then:
        r.outcome == COMPLETED
        items.last().z == 870f
    }

    def "#kind is a script error at its line: #message"() {
        when:
        def r = h.run(SQUARE + source, FILE)
        ScriptError error = r.error

        then:
        r.outcome == SCRIPT_ERROR
        error.file == FILE
        error.line == (SQUARE + source).readLines().findIndexOf { it.contains('<<') } + 1
        error.message.contains(message)

        where:
        kind | source || message
        'two vertices' | "mission {\n survey {\n  polygon corner(0, 0), corner(100, 0) // <<\n  altitude 50\n  spacing 20\n }\n}" || 'survey: a polygon needs at least 3 vertices, got 2'
        'across the antimeridian' | "mission {\n survey { // <<\n  polygon location(-17, 179.999, 0), location(-17, -179.999, 0), location(-16.999, -179.999, 0)\n  altitude 50\n  spacing 20\n }\n}" || 'antimeridian'
        'no overlap' | "mission {\n survey {\n  polygon corner(0, 0), corner(100, 0), corner(100, 100)\n  camera 'GoPro Hero 4'\n  altitude 50\n  sideOverlap 0 // <<\n }\n}" || 'survey: sideOverlap must be above 0 and below 100 %, got 0'
        'entire overlap' | "mission {\n survey {\n  polygon corner(0, 0), corner(100, 0), corner(100, 100)\n  camera 'GoPro Hero 4'\n  frontOverlap 100 // <<\n  altitude 50\n }\n}" || 'survey: frontOverlap must be above 0 and below 100 %, got 100: photos that overlap entirely never move on'
        'a zero focal length' | "mission {\n survey {\n  polygon corner(0, 0), corner(100, 0), corner(100, 100)\n  camera sensorWidth: 13.2, sensorHeight: 8.8, imageWidth: 5472, imageHeight: 3648, focalLength: 0 // <<\n  altitude 50\n }\n}" || 'focal length'
        'fractional pixels' | "mission {\n survey {\n  polygon corner(0, 0), corner(100, 0), corner(100, 100)\n  camera sensorWidth: 13.2, sensorHeight: 8.8, imageWidth: 5472.5, imageHeight: 3648, focalLength: 10 // <<\n }\n}" || 'survey: camera: imageWidth must be a whole number of pixels, got 5472.5'
        'an unknown camera' | "mission {\n survey {\n  camera 'Sony a6000 61mm' // <<\n }\n}" || "survey: camera: no camera named 'Sony a6000 61mm' (did you mean 'Sony a6000 16mm'"
        'no altitude' | "mission {\n survey { // <<\n  polygon corner(0, 0), corner(100, 0), corner(100, 100)\n  camera 'GoPro Hero 4'\n }\n}" || "survey: with a camera, give either 'altitude METRES' or 'gsd CM_PER_PX'"
        'no polygon' | "mission {\n survey { // <<\n  altitude 50\n  spacing 20\n }\n}" || 'survey: which area?'
        'a survey below the clearance' | "mission {\n survey { // <<\n  polygon corner(0, 0), corner(100, 0), corner(100, 100)\n  altitude 1\n  spacing 20\n }\n}" || 'is 1.0 m above home: lower than the 2 m clearance'
        'a fence polygon that is not there' | "mission {\n survey {\n  polygon fence: 1 // <<\n  altitude 50\n  spacing 20\n }\n}" || 'survey: polygon fence: 1: the mission\'s fence has no inclusion polygon'
        'a move after a survey without home' | "mission {\n survey {\n  polygon corner(0, 0), corner(100, 0), corner(100, 100)\n  altitude 50\n  spacing 20\n }\n move 10, 0 // <<\n}" || 'move: there is no position to start from: the survey ends at a height above home, and the mission names no home'
    }

    def "polygon fence: 1 surveys the mission's first inclusion polygon"() {
        when:
        def r = h.run(SQUARE + '''
            m = mission {
                home homePos
                fence {
                    inclusion polygon(corner(0, 0), corner(150, 0), corner(150, 150), corner(0, 150))
                }
                survey {
                    polygon fence: 1
                    altitude 40
                    spacing 25
                }
            }
        ''', FILE)
        PolygonSurvey s = mission('m').commandList.find { it instanceof PolygonSurvey } as PolygonSurvey

        then:
        r.outcome == COMPLETED
        s.polygon().size() == 4
        Math.abs(ned(s.polygon()[2].latitudeDegrees(), s.polygon()[2].longitudeDegrees())[0] - 150) < 0.01
    }
}
