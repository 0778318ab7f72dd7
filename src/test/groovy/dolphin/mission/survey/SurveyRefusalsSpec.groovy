package dolphin.mission.survey

import dolphin.core.Position
import spock.lang.Specification

import static dolphin.mission.survey.SurveyFixtures.*

/** What a mapping item refuses, and the message that says why. */
class SurveyRefusalsSpec extends Specification {

    static final PhotoGrid GRID = PhotoGrid.manual(50, 30, 25)
    static final TransectOptions OPTIONS = TransectOptions.defaults()

    static PolygonSurvey survey(List<Position> polygon) {
        new PolygonSurvey('survey', polygon, GRID, 0, EntryCorner.TOP_LEFT, false, OPTIONS)
    }

    static List<Position> degrees(List<List<Number>> latLon) {
        latLon.collect { Position.fromDegrees(it[0] as double, it[1] as double, 0) }
    }

    def "a survey polygon of two vertices"() {
        when:
        survey(SQUARE.take(2))

        then:
        IllegalArgumentException e = thrown()
        e.message == 'a survey polygon needs at least 3 vertices, got 2'
    }

    def "a polygon across the antimeridian"() {
        when:
        survey(degrees([[-17.0, 179.99], [-17.0, -179.99], [-17.01, -179.99], [-17.01, 179.99]]))

        then:
        IllegalArgumentException e = thrown()
        e.message.startsWith('the survey polygon crosses the antimeridian (180° longitude): its longitudes run from -179.99° to 179.99°')
        e.message.endsWith('split it into two surveys, one each side')
    }

    def "a polygon within 1° of a pole"() {
        when:
        survey(degrees([[89.5, 0], [89.5, 1], [89.4, 1]]))

        then:
        IllegalArgumentException e = thrown()
        e.message.startsWith("the survey polygon's vertex 0 at latitude 89.5° is within 1° of the North Pole")
    }

    def "a polygon that no transect crosses (no area: three vertices on one meridian)"() {
        when:
        survey(outline([[0, 0], [0, -100], [0, -50]]))

        then:
        IllegalArgumentException e = thrown()
        e.message.startsWith('no transect crosses the survey polygon at an angle of 0°')
    }

    def "corridor and structure refusals: #message"() {
        when:
        make()

        then:
        IllegalArgumentException e = thrown()
        e.message == message

        where:
        make | message
        ({ new CorridorScan('c', SQUARE.take(1), 10, GRID, EntryCorner.TOP_LEFT, OPTIONS) }) |
                'a corridor polyline needs at least 2 vertices, got 1'
        ({ new CorridorScan('c', SQUARE.take(2), -5, GRID, EntryCorner.TOP_LEFT, OPTIONS) }) |
                'the corridor width must be 0 m (one line along the polyline) or more, got -5'
        ({ new CorridorScan('c', SQUARE.take(2), 10, GRID, EntryCorner.TOP_LEFT, OPTIONS.withHoverAndCapture(true)) }) |
                'a corridor scan cannot hover and capture; it triggers the camera by distance'
        ({ new StructureScan('s', SQUARE.take(2), GRID, 30, 10, 40, true, 0) }) |
                'a structure polygon needs at least 3 vertices, got 2'
        ({ new StructureScan('s', SQUARE, GRID, 30, 40, 40, true, 0) }) |
                'the scan bottom (40 m) is above the structure height (30 m); the bottom must be at or below the top'
        ({ new StructureScan('s', SQUARE, PhotoGrid.manual(10, 8, 0), 30, 10, 40, true, 0) }) |
                "a structure scan needs a layer height (the photo grid's trigger distance) above 0 m, got 0"
        ({ TransectOptions.defaults().withTurnaround(-1) }) |
                'the turnaround distance must be 0 m or more, got -1'
    }

    def "entry corners parse as QGC names them, in words or as constants (#text)"() {
        expect:
        EntryCorner.parse(text) == corner

        where:
        text           | corner
        'topLeft'      | EntryCorner.TOP_LEFT
        'top right'    | EntryCorner.TOP_RIGHT
        'BOTTOM_LEFT'  | EntryCorner.BOTTOM_LEFT
        'bottom-right' | EntryCorner.BOTTOM_RIGHT
    }

    def "an unknown entry corner lists the four"() {
        when:
        EntryCorner.parse('middle')

        then:
        IllegalArgumentException e = thrown()
        e.message == "unknown entry corner 'middle': expected topLeft, topRight, bottomLeft or bottomRight"
    }

    def "QGC's numbers: entry 0..3, distance modes 1, 2, 4 (3 read as terrain)"() {
        expect:
        (0..3).collect { EntryCorner.ofQgc(it) } == EntryCorner.values().toList()
        HeightReference.values()*.qgcDistanceMode() == [1, 2, 4]
        [1, 2, 3, 4].collect { HeightReference.ofQgcDistanceMode(it) } ==
                [HeightReference.ABOVE_HOME, HeightReference.ABOVE_SEA_LEVEL, HeightReference.ABOVE_TERRAIN, HeightReference.ABOVE_TERRAIN]
    }
}
