package dolphin.mission.survey;

/** The parts of Qt's {@code QLineF} that QGroundControl's survey geometry relies on (docs/qgc-surveys.md §2.2, §3.1). */
final class QtLine {

    private QtLine() {
    }

    /** Where segments a1-a2 and b1-b2 cross, ends included; null if they do not (or are parallel). */
    static Xy boundedIntersection(Xy a1, Xy a2, Xy b1, Xy b2) {
        return intersection(a1, a2, b1, b2, true);
    }

    /** Where the infinite lines through a1-a2 and b1-b2 cross; null if they are parallel. */
    static Xy unboundedIntersection(Xy a1, Xy a2, Xy b1, Xy b2) {
        return intersection(a1, a2, b1, b2, false);
    }

    private static Xy intersection(Xy a1, Xy a2, Xy b1, Xy b2, boolean bounded) {
        double ax = a2.x() - a1.x();
        double ay = a2.y() - a1.y();
        double bx = b1.x() - b2.x();
        double by = b1.y() - b2.y();
        double denominator = ay * bx - ax * by;
        if (denominator == 0 || !Double.isFinite(denominator)) {
            return null;
        }
        double reciprocal = 1 / denominator;
        double cx = a1.x() - b1.x();
        double cy = a1.y() - b1.y();
        double na = (by * cx - bx * cy) * reciprocal;
        if (bounded) {
            double nb = (ax * cy - ay * cx) * reciprocal;
            if (na < 0 || na > 1 || nb < 0 || nb > 1) {
                return null;
            }
        }
        return new Xy(a1.x() + ax * na, a1.y() + ay * na);
    }

    /** Qt's {@code QPointF ==}: each coordinate equal to 12 significant digits, or both within 1e-12 of 0. */
    static boolean fuzzyEqual(Xy a, Xy b) {
        return fuzzyEqual(a.x(), b.x()) && fuzzyEqual(a.y(), b.y());
    }

    private static boolean fuzzyEqual(double a, double b) {
        if (a == 0 || b == 0) {
            return Math.abs(a - b) <= 1e-12;
        }
        return Math.abs(a - b) * 1e12 <= Math.min(Math.abs(a), Math.abs(b));
    }

    /** Qt's line angle: atan2(-dy, dx) in degrees, in [0, 360). */
    static double angle(Xy p1, Xy p2) {
        double deg = Math.toDegrees(Math.atan2(-(p2.y() - p1.y()), p2.x() - p1.x()));
        return deg < 0 ? deg + 360 : deg;
    }

    /** The end of a line from {@code from} of the given length at a Qt angle (QLineF setLength then setAngle). */
    static Xy polar(Xy from, double length, double angleDegrees) {
        double r = Math.toRadians(angleDegrees);
        return new Xy(from.x() + length * Math.cos(r), from.y() - length * Math.sin(r));
    }
}
