package dolphin.mission.dsl;

import dolphin.core.Position;
import dolphin.dsl.DslException;

/**
 * Checks of the arguments of the mission words. Each failure is a {@link DslException} that starts
 * with the word, so the engine reports it as {@code file:line: word: what was expected}. Values are
 * shown as the script wrote them ({@code got -5}, not {@code got -5.0}).
 */
public final class Args {

    /** Slack for latitudes and longitudes that went through radians and back. */
    private static final double ANGLE_SLACK = 1e-9;

    private Args() {
    }

    public static String show(Object v) {
        return v == null ? "null" : v.toString();
    }

    /** A finite number. */
    public static double number(String word, String what, Number v) {
        if (v == null) {
            throw new DslException(word + ": the " + what + " must be a number, got null");
        }
        double d = v.doubleValue();
        if (Double.isNaN(d) || Double.isInfinite(d)) {
            throw new DslException(word + ": the " + what + " must be a finite number, got " + show(v));
        }
        return d;
    }

    public static double latitude(String word, Number v) {
        double d = number(word, "latitude", v);
        if (d < -90 || d > 90) {
            throw new DslException(word + ": the latitude must be between -90 and 90 degrees, got " + show(v));
        }
        return d;
    }

    public static double longitude(String word, Number v) {
        double d = number(word, "longitude", v);
        if (d < -180 || d > 180) {
            throw new DslException(word + ": the longitude must be between -180 and 180 degrees, got " + show(v));
        }
        return d;
    }

    /** A position from degrees and metres above mean sea level. */
    public static Position position(String word, Number lat, Number lon, Number height) {
        double la = latitude(word, lat);
        double lo = longitude(word, lon);
        return Position.fromDegrees(la, lo, number(word, "height", height));
    }

    /** A position given as an object: not null, in range. */
    public static Position position(String word, Position p) {
        if (p == null) {
            throw new DslException(word + ": the position is null (a variable that holds no position?)");
        }
        double la = p.latitudeDegrees();
        double lo = p.longitudeDegrees();
        if (!(la >= -90 - ANGLE_SLACK && la <= 90 + ANGLE_SLACK)) {
            throw new DslException(word + ": the latitude must be between -90 and 90 degrees, got " + la);
        }
        if (!(lo >= -180 - ANGLE_SLACK && lo <= 180 + ANGLE_SLACK)) {
            throw new DslException(word + ": the longitude must be between -180 and 180 degrees, got " + lo);
        }
        if (Double.isNaN(p.hae()) || Double.isInfinite(p.hae())) {
            throw new DslException(word + ": the height must be a finite number, got " + p.hae());
        }
        return p;
    }

    public static float radius(String word, Number v) {
        return (float) notNegative(word, "radius", v);
    }

    public static double notNegative(String word, String what, Number v) {
        double d = number(word, what, v);
        if (d < 0) {
            throw new DslException(word + ": the " + what + " must not be negative, got " + show(v));
        }
        return d;
    }

    public static double positive(String word, String what, Number v) {
        double d = number(word, what, v);
        if (d <= 0) {
            throw new DslException(word + ": the " + what + " must be positive, got " + show(v));
        }
        return d;
    }

    /** A positive number of seconds, as a Duration (to the millisecond). */
    public static java.time.Duration duration(String word, String what, Number seconds) {
        return java.time.Duration.ofMillis(Math.round(positive(word, what, seconds) * 1000));
    }

    /** A whole number in [min, max]. */
    public static int whole(String word, String what, Number v, int min, int max) {
        double d = number(word, what, v);
        if (d != Math.rint(d)) {
            throw new DslException(word + ": the " + what + " must be a whole number, got " + show(v));
        }
        if (d < min) {
            throw new DslException(word + ": the " + what + (min == 0 ? " must not be negative" : " must be at least " + min)
                    + ", got " + show(v));
        }
        if (d > max) {
            throw new DslException(word + ": the " + what + " must be at most " + max + ", got " + show(v));
        }
        return (int) d;
    }

    /** A yaw in degrees, or NaN for "keep the vehicle's yaw mode". */
    public static float yaw(String word, Number v) {
        if (v == null) {
            throw new DslException(word + ": the yaw must be a number of degrees or NaN, got null");
        }
        double d = v.doubleValue();
        if (Double.isInfinite(d)) {
            throw new DslException(word + ": the yaw must be a number of degrees or NaN, got " + show(v));
        }
        return (float) d;
    }

    /** PRECISION_LAND_MODE: 0 disabled, 1 opportunistic, 2 required. */
    public static int landMode(String word, Number v) {
        double d = number(word, "land mode", v);
        if (d != 0 && d != 1 && d != 2) {
            throw new DslException(word + ": the land mode must be 0 (disabled), 1 (opportunistic) or 2 (required), got "
                    + show(v));
        }
        return (int) d;
    }

    /** The speed type of DO_CHANGE_SPEED: 0 airspeed, 1 ground speed, 2 climb, 3 descent. */
    public static int speedType(String word, Number v) {
        double d = number(word, "speed type", v);
        if (d != 0 && d != 1 && d != 2 && d != 3) {
            throw new DslException(word + ": the speed type must be 0 (airspeed), 1 (ground speed), 2 (climb) or"
                    + " 3 (descent), got " + show(v));
        }
        return (int) d;
    }
}
