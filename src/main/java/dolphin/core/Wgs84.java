package dolphin.core;

/**
 * WGS-84 conversions as the original engine computes them (docs/decisions.md, "Heights and
 * positions"), including the geocentric latitude used when displacing, so coordinates match the
 * original's.
 */
public final class Wgs84 {

    public static final double A = 6378137.0;
    public static final double E2 = 0.00669437999013;

    private Wgs84() {
    }

    /** Radius of curvature in the prime vertical at geodetic latitude phi (radians). */
    static double n(double phi) {
        double s = Math.sin(phi);
        return A / Math.sqrt(1 - E2 * s * s);
    }

    /** Geodetic (radians, radians, metres) to ECEF (x, y, z) metres. */
    public static double[] toEcef(double lat, double lon, double hae) {
        double n = n(lat);
        return new double[] {
            (n + hae) * Math.cos(lat) * Math.cos(lon),
            (n + hae) * Math.cos(lat) * Math.sin(lon),
            ((1 - E2) * n + hae) * Math.sin(lat)
        };
    }

    /** ECEF to geodetic, iterating until the height changes by at most 0.1 mm. */
    public static Position fromEcef(double x, double y, double z) {
        double p = Math.sqrt(x * x + y * y);
        double lon = Math.atan2(y, x);
        double lat = Math.atan2(z / p, 0.01);
        double n = n(lat);
        double h = p / Math.cos(lat) - n;
        // At least one refinement: the first guess's height can fall within 0.1 mm of any start value (at
        // the equator, at sea level), and the first guess's latitude is far off.
        double previous = Double.POSITIVE_INFINITY;
        while (Math.abs(h - previous) > 1e-4) {
            previous = h;
            lat = Math.atan2(z / p, 1 - E2 * n / (n + h));
            n = n(lat);
            h = p / Math.cos(lat) - n;
        }
        return new Position(lat, lon, h);
    }

    /** The displacement from a to b as (north, east, down) metres, in a's local frame. */
    public static double[] ned(Position a, Position b) {
        double[] pa = toEcef(a.lat(), a.lon(), a.hae());
        double[] pb = toEcef(b.lat(), b.lon(), b.hae());
        double dx = pb[0] - pa[0];
        double dy = pb[1] - pa[1];
        double dz = pb[2] - pa[2];
        double sp = Math.sin(a.lat());
        double cp = Math.cos(a.lat());
        double sl = Math.sin(a.lon());
        double cl = Math.cos(a.lon());
        return new double[] {
            -sp * cl * dx - sp * sl * dy + cp * dz,
            -sl * dx + cl * dy,
            -cp * cl * dx - cp * sl * dy - sp * dz
        };
    }

    /** p moved by (north, east, down) metres. */
    public static Position displace(Position p, double north, double east, double down) {
        double[] e = toEcef(p.lat(), p.lon(), p.hae());
        double psi = Math.atan2(e[2], Math.sqrt(e[0] * e[0] + e[1] * e[1]));
        double sl = Math.sin(p.lon());
        double cl = Math.cos(p.lon());
        double sp = Math.sin(psi);
        double cp = Math.cos(psi);
        return fromEcef(
                e[0] - sl * east - cl * sp * north - cl * cp * down,
                e[1] + cl * east - sl * sp * north - sl * cp * down,
                e[2] + cp * north - sp * down);
    }
}
