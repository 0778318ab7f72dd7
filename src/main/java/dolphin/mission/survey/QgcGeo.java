package dolphin.mission.survey;

/**
 * The two spherical models QGroundControl mixes (docs/qgc-surveys.md §2.1): the azimuthal
 * equidistant projection of the QGC releases that wrote the plans we match (R = 6 371 000 m,
 * x east, y north) for transect geometry, and Qt's {@code QGeoCoordinate} great-circle helpers
 * (R = 6 371 007.2 m) for turnarounds, hover points and distances. The operations follow QGC's
 * and Qt's order, and StrictMath gives the same last bits on every machine: those bits decide
 * whether a grid line that grazes a vertex makes a transect.
 */
final class QgcGeo {

    static final double PROJECTION_RADIUS = 6_371_000.0;
    /** Qt's qgeocoordinate_EARTH_MEAN_RADIUS (km) times 1000, computed as Qt does. */
    static final double QT_RADIUS = 6371.0072 * 1000.0;
    private static final double EPSILON = 2.220446049250313e-16;

    private QgcGeo() {
    }

    /** The point in the plane tangent at {@code origin}; the origin itself is exactly (0, 0), as in QGC. */
    static Xy toPlane(GeoPoint origin, GeoPoint p) {
        if (p.equals(origin)) {
            return new Xy(0, 0);
        }
        double lat = Math.toRadians(p.lat());
        double lat0 = Math.toRadians(origin.lat());
        double dLon = Math.toRadians(p.lon()) - Math.toRadians(origin.lon());
        double sinLat = StrictMath.sin(lat);
        double cosLat = StrictMath.cos(lat);
        double sinLat0 = StrictMath.sin(lat0);
        double cosLat0 = StrictMath.cos(lat0);
        double cosDLon = StrictMath.cos(dLon);
        double c = StrictMath.acos(Math.max(-1, Math.min(1, sinLat0 * sinLat + cosLat0 * cosLat * cosDLon)));
        double k = Math.abs(c) < EPSILON ? 1 : c / StrictMath.sin(c);
        double north = k * (cosLat0 * sinLat - sinLat0 * cosLat * cosDLon) * PROJECTION_RADIUS;
        double east = k * cosLat * StrictMath.sin(dLon) * PROJECTION_RADIUS;
        return new Xy(east, north);
    }

    /** The inverse of {@link #toPlane}; like QGC it leaves the longitude un-normalised. */
    static GeoPoint toGeo(GeoPoint origin, Xy p) {
        double n = p.y() / PROJECTION_RADIUS;
        double e = p.x() / PROJECTION_RADIUS;
        double c = StrictMath.sqrt(n * n + e * e);
        if (Math.abs(c) <= EPSILON) {
            return origin;
        }
        double lat0 = Math.toRadians(origin.lat());
        double sinC = StrictMath.sin(c);
        double cosC = StrictMath.cos(c);
        double sinLat0 = StrictMath.sin(lat0);
        double cosLat0 = StrictMath.cos(lat0);
        double lat = StrictMath.asin(cosC * sinLat0 + n * sinC * cosLat0 / c);
        double lon = Math.toRadians(origin.lon()) + StrictMath.atan2(e * sinC, c * cosLat0 * cosC - n * sinLat0 * sinC);
        return new GeoPoint(Math.toDegrees(lat), Math.toDegrees(lon));
    }

    /** Qt's {@code distanceTo}: haversine, metres. */
    static double distance(GeoPoint a, GeoPoint b) {
        double sinLat = StrictMath.sin(Math.toRadians(b.lat() - a.lat()) / 2);
        double sinLon = StrictMath.sin(Math.toRadians(b.lon() - a.lon()) / 2);
        double y = sinLat * sinLat + StrictMath.cos(Math.toRadians(a.lat())) * StrictMath.cos(Math.toRadians(b.lat()))
                * sinLon * sinLon;
        return 2 * StrictMath.asin(StrictMath.sqrt(y)) * QT_RADIUS;
    }

    /** Qt's {@code azimuthTo}: the initial great-circle bearing, degrees in [0, 360). */
    static double azimuth(GeoPoint a, GeoPoint b) {
        double dLon = Math.toRadians(b.lon() - a.lon());
        double lat1 = Math.toRadians(a.lat());
        double lat2 = Math.toRadians(b.lat());
        double y = StrictMath.sin(dLon) * StrictMath.cos(lat2);
        double x = StrictMath.cos(lat1) * StrictMath.sin(lat2)
                - StrictMath.sin(lat1) * StrictMath.cos(lat2) * StrictMath.cos(dLon);
        double azimuth = Math.toDegrees(StrictMath.atan2(y, x)) + 360.0;
        double whole = azimuth < 0 ? Math.ceil(azimuth) : Math.floor(azimuth);
        return ((int) whole + 360) % 360 + (azimuth - whole);
    }

    /** Qt's {@code atDistanceAndAzimuth}: a negative distance moves backwards. */
    static GeoPoint destination(GeoPoint a, double distance, double azimuthDegrees) {
        double lat1 = Math.toRadians(a.lat());
        double lon1 = Math.toRadians(a.lon());
        double cosLat1 = StrictMath.cos(lat1);
        double sinLat1 = StrictMath.sin(lat1);
        double az = Math.toRadians(azimuthDegrees);
        double ratio = distance / QT_RADIUS;
        double cosRatio = StrictMath.cos(ratio);
        double sinRatio = StrictMath.sin(ratio);
        double lat2 = StrictMath.asin(sinLat1 * cosRatio + cosLat1 * sinRatio * StrictMath.cos(az));
        double lon2 = lon1 + StrictMath.atan2(StrictMath.sin(az) * sinRatio * cosLat1,
                cosRatio - sinLat1 * StrictMath.sin(lat2));
        double lon = Math.toDegrees(lon2);
        // Qt's wrapLong: one step, not a modulo, so ordinary longitudes keep every bit
        if (lon > 180) {
            lon -= 360;
        } else if (lon < -180) {
            lon += 360;
        }
        return new GeoPoint(Math.toDegrees(lat2), lon);
    }
}
