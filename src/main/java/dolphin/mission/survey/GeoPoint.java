package dolphin.mission.survey;

import dolphin.core.Position;

/** A latitude and longitude in degrees: the points the survey geometry works with. */
record GeoPoint(double lat, double lon) {

    static GeoPoint of(Position p) {
        return new GeoPoint(p.latitudeDegrees(), p.longitudeDegrees());
    }

    Position position() {
        return Position.fromDegrees(lat, lon, 0);
    }

    TransectPoint as(TransectPoint.PointKind kind) {
        return new TransectPoint(lat, lon, kind);
    }
}
