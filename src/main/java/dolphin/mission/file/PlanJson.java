package dolphin.mission.file;

import java.util.List;
import java.util.Map;

/**
 * Typed reads of QGroundControl's JSON with the path of each value in the error, e.g.
 * "mission.items[3].params: expected a number or null, found "abc"".
 */
final class PlanJson {

    private PlanJson() {
    }

    static Map<?, ?> map(Object v, String where) {
        if (!(v instanceof Map<?, ?> m)) {
            throw new IllegalArgumentException(where + ": expected a JSON object, found " + shown(v));
        }
        return m;
    }

    static List<?> list(Object v, String where) {
        if (!(v instanceof List<?> l)) {
            throw new IllegalArgumentException(where + ": expected a JSON array, found " + shown(v));
        }
        return l;
    }

    /** A number, or null as NaN (QGroundControl writes NaN as null). */
    static float toFloat(Object v, String where) {
        if (v == null) {
            return Float.NaN;
        }
        if (!(v instanceof Number)) {
            throw new IllegalArgumentException(where + ": expected a number or null, found " + shown(v));
        }
        return FileValues.parseFloat(v.toString());
    }

    static double toDouble(Object v, String where) {
        if (!(v instanceof Number n)) {
            throw new IllegalArgumentException(where + ": expected a number, found " + shown(v));
        }
        return n.doubleValue();
    }

    /** Degrees of latitude (limit 90) or longitude (limit 180) as degE7; null as 0 (no position). */
    static int degE7(Object v, double limit, String where) {
        if (v == null) {
            return 0;
        }
        if (!(v instanceof Number)) {
            throw new IllegalArgumentException(where + ": expected degrees, found " + shown(v));
        }
        try {
            return FileValues.degE7(v.toString(), limit);
        } catch (NumberFormatException | ArithmeticException e) {
            throw new IllegalArgumentException(where + ": " + e.getMessage(), e);
        }
    }

    /** Degrees of latitude (limit 90) or longitude (limit 180) as they are written, refused when missing or out of range. */
    static double degrees(Object v, double limit, String where) {
        if (!(v instanceof Number n) || !Double.isFinite(n.doubleValue())) {
            throw new IllegalArgumentException(where + ": expected degrees of " + (limit == 90 ? "latitude" : "longitude")
                    + ", found " + shown(v));
        }
        double d = n.doubleValue();
        if (Math.abs(d) > limit) {
            throw new IllegalArgumentException(where + ": " + n + " is out of range for a "
                    + (limit == 90 ? "latitude (-90 to 90)" : "longitude (-180 to 180)"));
        }
        return d;
    }

    static int integer(Object v, String where) {
        if (!(v instanceof Number n)) {
            throw new IllegalArgumentException(where + ": expected an integer, found " + shown(v));
        }
        try {
            return FileValues.parseInt(n.toString());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(where + ": " + e.getMessage(), e);
        }
    }

    static boolean bool(Object v, String where) {
        if (!(v instanceof Boolean b)) {
            throw new IllegalArgumentException(where + ": expected true or false, found " + shown(v));
        }
        return b;
    }

    /** A version number: an integer, or a string such as "1.0" (QGroundControl's first .mission files). */
    static double version(Object v, String where) {
        if (v instanceof Number n) {
            return n.doubleValue();
        }
        if (v instanceof String s) {
            try {
                return Double.parseDouble(s.strip());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(where + ": expected a version number, found \"" + s + "\"", e);
            }
        }
        throw new IllegalArgumentException(where + ": expected a version number, found " + shown(v));
    }

    private static String shown(Object v) {
        if (v == null) {
            return "nothing";
        }
        String s = v instanceof String str ? "\"" + str + "\"" : v.toString();
        return s.length() <= 60 ? s : s.substring(0, 60) + "...";
    }
}
