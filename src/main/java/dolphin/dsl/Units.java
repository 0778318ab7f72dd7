package dolphin.dsl;

import dolphin.dsl.vocabulary.Word;

/**
 * The units of the Dolphin language as a Groovy category ({@code 10.minutes}, {@code 2.km}). The
 * engine activates it only on the script thread while a script runs, so other Groovy code in the
 * same JVM is not affected. Base units: metres, degrees, seconds.
 */
public final class Units {

    private Units() {
    }

    @Word("Kilometres, as metres: 2.km")
    public static double getKm(Number n) {
        return n.doubleValue() * 1000;
    }

    @Word("Kilometres, as metres")
    public static double getKilometers(Number n) {
        return getKm(n);
    }

    @Word("Metres")
    public static double getMeters(Number n) {
        return n.doubleValue();
    }

    @Word("Degrees")
    public static double getDegrees(Number n) {
        return n.doubleValue();
    }

    /** A value given in radians, as degrees. */
    @Word("Radians, as degrees")
    public static double getRadians(Number n) {
        return Math.toDegrees(n.doubleValue());
    }

    @Word("Metres north")
    public static double getNorth(Number n) {
        return n.doubleValue();
    }

    @Word("Metres east")
    public static double getEast(Number n) {
        return n.doubleValue();
    }

    @Word("Metres south (a negative north)")
    public static double getSouth(Number n) {
        return -n.doubleValue();
    }

    @Word("Metres west (a negative east)")
    public static double getWest(Number n) {
        return -n.doubleValue();
    }

    @Word("Seconds")
    public static double getSeconds(Number n) {
        return n.doubleValue();
    }

    @Word("Minutes, as seconds: 10.minutes")
    public static double getMinutes(Number n) {
        return n.doubleValue() * 60;
    }

    @Word("Hours, as seconds")
    public static double getHours(Number n) {
        return n.doubleValue() * 3600;
    }

    @Word("Days, as seconds")
    public static double getDays(Number n) {
        return n.doubleValue() * 86400;
    }

    @Word("A percentage, as a fraction: 90.percent is 0.9")
    public static double getPercent(Number n) {
        return n.doubleValue() * 0.01;
    }
}
