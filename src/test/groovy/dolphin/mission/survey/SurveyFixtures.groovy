package dolphin.mission.survey

import dolphin.core.Position

/**
 * Outlines for the survey specs, laid out in metres east and north of a corner at PX4's Zürich
 * test site on QGroundControl's sphere (R = 6 371 000 m), and the way back from a point to metres.
 * At these sizes the flat approximation is good to about 0.1 mm.
 */
class SurveyFixtures {

    static final double LAT0 = 47.397742, LON0 = 8.545594
    static final double M_PER_DEG = 6_371_000 * Math.PI / 180

    /** The place {@code east} m east and {@code north} m north of (LAT0, LON0). */
    static Position at(double east, double north) {
        Position.fromDegrees(LAT0 + north / M_PER_DEG, LON0 + east / (M_PER_DEG * Math.cos(Math.toRadians(LAT0))), 0)
    }

    static List<Position> outline(List<List<Number>> eastNorth) {
        eastNorth.collect { at(it[0] as double, it[1] as double) }
    }

    /** [east, north] metres of a latitude/longitude in degrees. */
    static List<Double> metres(double lat, double lon) {
        [(lon - LON0) * M_PER_DEG * Math.cos(Math.toRadians(LAT0)), (lat - LAT0) * M_PER_DEG]
    }

    static List<Double> metres(TransectPoint p) { metres(p.latitude(), p.longitude()) }

    static List<Double> metres(Position p) { metres(p.latitudeDegrees(), p.longitudeDegrees()) }

    static boolean near(List<Double> a, List<Number> b, double tolerance = 0.01) {
        Math.hypot(a[0] - (b[0] as double), a[1] - (b[1] as double)) <= tolerance
    }

    /** A 100 m square, vertex 0 its north-west corner, clockwise. */
    static final List<Position> SQUARE = outline([[0, 0], [100, 0], [100, -100], [0, -100]])

    /** A U open to the north: 300 m wide and deep, the notch 100 m wide and 200 m deep in the middle. */
    static final List<Position> U = outline([[0, 0], [100, 0], [100, -200], [200, -200], [200, 0], [300, 0], [300, -300], [0, -300]])
}
