package dolphin.mission.file;

import dolphin.mission.model.ItemText;
import dolphin.mission.model.Mission;
import dolphin.mission.model.MissionItem;
import groovy.json.JsonOutput;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.List;
import java.util.Locale;

/**
 * What the mission file formats share beyond {@link ItemText}: degrees read from text, JSON numbers,
 * parsing, and the home item every mission file has.
 */
final class FileValues {

    private FileValues() {
    }

    /** Degrees (any decimal text) to degE7, rounded half-even; NaN and infinities give 0 (no position). */
    static int degE7(String text) {
        long e7 = parseDegE7(text);
        if (Math.abs(e7) > 1_800_000_000L) {
            throw new NumberFormatException(text + " degrees is out of range");
        }
        return (int) e7;
    }

    /**
     * Degrees of latitude ({@code limit} 90) or longitude (180) to degE7, refused out of range.
     *
     * @throws NumberFormatException saying which, e.g. "95.2 is out of range for a latitude (-90 to 90)"
     */
    static int degE7(String text, double limit) {
        long e7 = parseDegE7(text);
        if (Math.abs(e7) > limit * 1e7) {
            throw new NumberFormatException(text.strip() + " is out of range for a "
                    + (limit == 90 ? "latitude (-90 to 90)" : "longitude (-180 to 180)"));
        }
        return (int) e7;
    }

    private static long parseDegE7(String text) {
        String t = text.strip();
        if (isNonFinite(t)) {
            return 0;
        }
        try {
            return new BigDecimal(t).movePointRight(7).setScale(0, RoundingMode.HALF_EVEN).longValueExact();
        } catch (NumberFormatException e) {
            throw new NumberFormatException("'" + text + "' is not a number of degrees");
        } catch (ArithmeticException e) {
            throw new NumberFormatException(text + " degrees is out of range");
        }
    }

    /**
     * A float as a JSON number, written verbatim: {@link ItemText#number}'s text, or Java's exponent form for
     * very large and very small magnitudes (JSON readers mishandle integers past 2^63); -0 as "-0.0".
     * Null for NaN and infinities, which JSON cannot carry (QGroundControl writes null for NaN).
     */
    static Object jsonNumber(float f) {
        if (!Float.isFinite(f)) {
            return null;
        }
        String s = ItemText.number(f);
        if (s.equals("-0")) {
            s = "-0.0";
        } else if (s.length() > 15) {
            s = Float.toString(f);
        }
        return JsonOutput.unescaped(s);
    }

    /**
     * A double as a JSON number, written verbatim: an integer without a fraction, otherwise Java's
     * decimal that reads back to the same double. Null for NaN and infinities, as {@link #jsonNumber}.
     */
    static Object jsonDouble(double d) {
        if (!Double.isFinite(d)) {
            return null;
        }
        if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            return JsonOutput.unescaped(d == 0 && 1 / d < 0 ? "-0.0" : Long.toString((long) d));
        }
        return JsonOutput.unescaped(Double.toString(d));
    }

    /** degE7 as JSON degrees, written verbatim without trailing zeros: 404442330 -> 40.444233. */
    static Object jsonDegrees(int degE7) {
        return JsonOutput.unescaped(BigDecimal.valueOf(degE7, 7).stripTrailingZeros().toPlainString());
    }

    /** Reads a float written by {@link ItemText#number} or by other tools ("NaN", "nan", "inf", "1.5e3", ...). */
    static float parseFloat(String text) {
        String t = text.strip().toLowerCase(Locale.ROOT);
        switch (t) {
            case "nan", "+nan", "-nan":
                return Float.NaN;
            case "inf", "+inf", "infinity", "+infinity":
                return Float.POSITIVE_INFINITY;
            case "-inf", "-infinity":
                return Float.NEGATIVE_INFINITY;
            default:
                if (!t.matches("[-+]?(\\d+\\.?\\d*|\\.\\d+)(e[-+]?\\d+)?")) {
                    throw new NumberFormatException("'" + text + "' is not a number");
                }
                return Float.parseFloat(t);
        }
    }

    static int parseInt(String text) {
        String t = text.strip();
        try {
            return Integer.parseInt(t);
        } catch (NumberFormatException e) {
            // Some tools write integers as floats ("16.0").
            try {
                return new BigDecimal(t).intValueExact();
            } catch (NumberFormatException | ArithmeticException e2) {
                throw new NumberFormatException("'" + text + "' is not an integer");
            }
        }
    }

    private static boolean isNonFinite(String t) {
        String l = t.toLowerCase(Locale.ROOT);
        return l.contains("nan") || l.contains("inf");
    }

    /** A JSON object with its keys in the given order: {@code ordered("type", "Point", "coordinates", c)}. */
    static java.util.Map<String, Object> ordered(Object... keysAndValues) {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        for (int i = 0; i < keysAndValues.length; i += 2) {
            m.put((String) keysAndValues[i], keysAndValues[i + 1]);
        }
        return m;
    }

    /** The items must begin with the home item (seq 0), as {@link Mission#items} gives them. */
    static void requireHome(List<MissionItem> items) {
        if (items.isEmpty()) {
            throw new IllegalArgumentException("a mission file needs at least the home item (seq 0)");
        }
    }
}
