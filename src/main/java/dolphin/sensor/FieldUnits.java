package dolphin.sensor;

import java.util.Map;

/**
 * How a telemetry field's MAVLink unit becomes the unit scripts get: Dolphin's units are degrees,
 * metres, seconds, m/s, volts and amperes, so scaled units are converted (degE7 to degrees, mm and cm
 * to metres, cdeg to degrees, ms to seconds, mV to volts) and radians become degrees. The table is
 * docs/sensors.md's, "Telemetry units"; units not in it are kept as MAVLink defines them.
 */
final class FieldUnits {

    /** A MAVLink unit's factor to the script's unit, and that unit. */
    record Conversion(double factor, String unit) {
    }

    private static final double DEG_PER_RAD = 180 / Math.PI;

    private static final Map<String, Conversion> TABLE = Map.ofEntries(
            Map.entry("degE7", new Conversion(1e-7, "deg")),
            Map.entry("degE5", new Conversion(1e-5, "deg")),
            Map.entry("cdeg", new Conversion(0.01, "deg")),
            Map.entry("deg/2", new Conversion(2, "deg")),
            Map.entry("rad", new Conversion(DEG_PER_RAD, "deg")),
            Map.entry("rad/s", new Conversion(DEG_PER_RAD, "deg/s")),
            Map.entry("mrad/s", new Conversion(DEG_PER_RAD / 1000, "deg/s")),
            Map.entry("ddeg/s", new Conversion(0.1, "deg/s")),
            Map.entry("mm", new Conversion(0.001, "m")),
            Map.entry("cm", new Conversion(0.01, "m")),
            Map.entry("dm", new Conversion(0.1, "m")),
            Map.entry("dam", new Conversion(10, "m")),
            Map.entry("mm/s", new Conversion(0.001, "m/s")),
            Map.entry("cm/s", new Conversion(0.01, "m/s")),
            Map.entry("dm/s", new Conversion(0.1, "m/s")),
            Map.entry("m/s*5", new Conversion(5, "m/s")),
            Map.entry("ms", new Conversion(1e-3, "s")),
            Map.entry("us", new Conversion(1e-6, "s")),
            Map.entry("ns", new Conversion(1e-9, "s")),
            Map.entry("cs", new Conversion(0.01, "s")),
            Map.entry("ds", new Conversion(0.1, "s")),
            Map.entry("cdegC", new Conversion(0.01, "degC")),
            Map.entry("mV", new Conversion(1e-3, "V")),
            Map.entry("cV", new Conversion(0.01, "V")),
            Map.entry("mA", new Conversion(1e-3, "A")),
            Map.entry("cA", new Conversion(0.01, "A")),
            Map.entry("d%", new Conversion(0.1, "%")),
            Map.entry("c%", new Conversion(0.01, "%")),
            Map.entry("mgauss", new Conversion(1e-3, "gauss")),
            Map.entry("mbar", new Conversion(1, "hPa")));

    private FieldUnits() {
    }

    /** The conversion of a MAVLink unit; factor 1 and the unit itself for units not converted. */
    static Conversion of(String mavlinkUnit) {
        return TABLE.getOrDefault(mavlinkUnit, new Conversion(1, mavlinkUnit));
    }

    static Map<String, Conversion> table() {
        return TABLE;
    }
}
