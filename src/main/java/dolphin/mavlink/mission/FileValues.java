package dolphin.mavlink.mission;

import com.MAVLink.enums.MAV_FRAME;
import groovy.json.JsonOutput;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.List;
import java.util.Locale;

/**
 * What the mission file formats share: numbers as text, degE7 as degrees, and the frames files use.
 *
 * <p>Files carry latitude and longitude as floating degrees, like MISSION_ITEM, so they name the
 * float frames (MAV_FRAME_GLOBAL, GLOBAL_RELATIVE_ALT, GLOBAL_TERRAIN_ALT), as QGroundControl and
 * Mission Planner write them; our items use the _INT frames of MISSION_ITEM_INT. Writing maps
 * GLOBAL_INT to GLOBAL (and the other two likewise), reading maps them back; other frames pass
 * unchanged. x and y are degrees (degE7 / 10^7) in every frame, as ArduPilot reads MISSION_ITEM.
 */
final class FileValues {

    private FileValues() {
    }

    /** The frame a file names for an item's frame. */
    static int fileFrame(int frame) {
        return switch (frame) {
            case MAV_FRAME.MAV_FRAME_GLOBAL_INT -> MAV_FRAME.MAV_FRAME_GLOBAL;
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT -> MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT;
            case MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT -> MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT;
            default -> frame;
        };
    }

    /** The item frame for a frame read from a file. */
    static int itemFrame(int fileFrame) {
        return switch (fileFrame) {
            case MAV_FRAME.MAV_FRAME_GLOBAL -> MAV_FRAME.MAV_FRAME_GLOBAL_INT;
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT -> MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT;
            case MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT -> MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT;
            default -> fileFrame;
        };
    }

    /** True for the frames whose x, y, z are a latitude, longitude and altitude. */
    static boolean isGlobal(int frame) {
        return switch (itemFrame(frame)) {
            case MAV_FRAME.MAV_FRAME_GLOBAL_INT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                    MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT -> true;
            default -> false;
        };
    }

    /** degE7 as exact degrees with 7 decimals, e.g. 404442330 -> "40.4442330". */
    static String degrees(int degE7) {
        return BigDecimal.valueOf(degE7, 7).toPlainString();
    }

    /** degE7 as the nearest double in degrees; writes back to the same degE7 through {@link #degE7(String)}. */
    static double degreesValue(int degE7) {
        return degE7 / 1e7;
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
     * A float as the shortest decimal that reads back to it, without an exponent; "nan", "inf" and
     * "-inf" as Python writes them (pymavlink reads them with float()); -0 keeps its sign.
     */
    static String number(float f) {
        if (Float.isNaN(f)) {
            return "nan";
        }
        if (Float.isInfinite(f)) {
            return f > 0 ? "inf" : "-inf";
        }
        if (f == 0) {
            return Float.floatToRawIntBits(f) == 0 ? "0" : "-0";
        }
        return new BigDecimal(Float.toString(f)).stripTrailingZeros().toPlainString();
    }

    /**
     * A float as a JSON number, written verbatim: {@link #number}'s text, or Java's exponent form for
     * very large and very small magnitudes (JSON readers mishandle integers past 2^63); -0 as "-0.0".
     * Null for NaN and infinities, which JSON cannot carry (QGroundControl writes null for NaN).
     */
    static Object jsonNumber(float f) {
        if (!Float.isFinite(f)) {
            return null;
        }
        String s = number(f);
        if (s.equals("-0")) {
            s = "-0.0";
        } else if (s.length() > 15) {
            s = Float.toString(f);
        }
        return JsonOutput.unescaped(s);
    }

    /** degE7 as JSON degrees, written verbatim without trailing zeros: 404442330 -> 40.444233. */
    static Object jsonDegrees(int degE7) {
        return JsonOutput.unescaped(BigDecimal.valueOf(degE7, 7).stripTrailingZeros().toPlainString());
    }

    /** Reads a float written by {@link #number} or by other tools ("NaN", "nan", "inf", "1.5e3", ...). */
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
