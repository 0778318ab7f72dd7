package dolphin.mission.survey;

/**
 * One coordinate flown by a survey, in degrees, with its role (QGC's CoordType): turnaround (outside
 * the area), entry and exit of a transect's camera section, a corridor's interior bend, a
 * hover-and-capture stop.
 */
public record TransectPoint(double latitude, double longitude, PointKind kind) {

    /** The role of a point (named PointKind: one simple name per class across the code base). */
    public enum PointKind { TURNAROUND, ENTRY, INTERIOR, HOVER, EXIT }

    GeoPoint geo() {
        return new GeoPoint(latitude, longitude);
    }

    TransectPoint withKind(PointKind k) {
        return new TransectPoint(latitude, longitude, k);
    }
}
