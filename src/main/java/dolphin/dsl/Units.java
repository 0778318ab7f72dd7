package dolphin.dsl;

/**
 * The units of the Dolphin language as a Groovy category ({@code 10.minutes}, {@code 2.km}). The
 * engine activates it only on the script thread while a script runs, so other Groovy code in the
 * same JVM is not affected. Base units: metres, degrees, seconds.
 */
public final class Units {

    private Units() {
    }

    public static double getKm(Number n) {
        return n.doubleValue() * 1000;
    }

    public static double getKilometers(Number n) {
        return getKm(n);
    }

    public static double getMeters(Number n) {
        return n.doubleValue();
    }

    public static double getDegrees(Number n) {
        return n.doubleValue();
    }

    /** A value given in radians, as degrees. */
    public static double getRadians(Number n) {
        return Math.toDegrees(n.doubleValue());
    }

    public static double getNorth(Number n) {
        return n.doubleValue();
    }

    public static double getEast(Number n) {
        return n.doubleValue();
    }

    public static double getSouth(Number n) {
        return -n.doubleValue();
    }

    public static double getWest(Number n) {
        return -n.doubleValue();
    }

    public static double getSeconds(Number n) {
        return n.doubleValue();
    }

    public static double getMinutes(Number n) {
        return n.doubleValue() * 60;
    }

    public static double getHours(Number n) {
        return n.doubleValue() * 3600;
    }

    public static double getDays(Number n) {
        return n.doubleValue() * 86400;
    }

    public static double getPercent(Number n) {
        return n.doubleValue() * 0.01;
    }
}
