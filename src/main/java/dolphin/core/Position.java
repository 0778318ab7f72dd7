package dolphin.core;

/**
 * An immutable WGS-84 position: latitude and longitude in radians, height in metres. In this
 * project heights are above mean sea level (docs/decisions.md, "Heights and positions").
 */
public record Position(double lat, double lon, double hae) {

    public static Position fromDegrees(double latDeg, double lonDeg, double hae) {
        return new Position(Math.toRadians(latDeg), Math.toRadians(lonDeg), hae);
    }

    public double latitudeDegrees() {
        return Math.toDegrees(lat);
    }

    public double longitudeDegrees() {
        return Math.toDegrees(lon);
    }

    /** Straight-line (ECEF) distance in metres. */
    public double distanceTo(Position other) {
        double[] a = Wgs84.toEcef(lat, lon, hae);
        double[] b = Wgs84.toEcef(other.lat, other.lon, other.hae);
        return Math.sqrt(sq(a[0] - b[0]) + sq(a[1] - b[1]) + sq(a[2] - b[2]));
    }

    /** Distance on the ground in metres: to {@code other} brought to this position's height. */
    public double horizontalDistanceTo(Position other) {
        double[] ned = Wgs84.ned(this, other.atHeight(hae));
        return Math.hypot(ned[0], ned[1]);
    }

    public boolean near(Position other, double radius) {
        return distanceTo(other) <= radius;
    }

    /** (north, east, down) metres from this position to {@code other}. */
    public double[] displacementTo(Position other) {
        return Wgs84.ned(this, other);
    }

    /** The same place at another height. */
    public Position atHeight(double height) {
        return new Position(lat, lon, height);
    }

    /** This position moved by (north, east, down) metres. */
    public Position displace(double north, double east, double down) {
        return Wgs84.displace(this, north, east, down);
    }

    /** {@code position ^ radius}: the area within radius metres. */
    public Area xor(Number radius) {
        return new Area(this, radius.doubleValue());
    }

    private static double sq(double v) {
        return v * v;
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "(%.6f°, %.6f°, %.3f)", latitudeDegrees(), longitudeDegrees(), hae);
    }
}
