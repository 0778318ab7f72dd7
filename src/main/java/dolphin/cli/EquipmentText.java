package dolphin.cli;

import dolphin.core.Position;
import dolphin.sim.LinearField;
import dolphin.sim.PlumeField;
import dolphin.sim.SimField;
import dolphin.sim.SimSensor;
import dolphin.sim.SysidSet;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The simulated fleet's sensors and cameras as the command line writes them; a bad one is an IllegalArgumentException saying why. */
final class EquipmentText {

    static final String SENSOR_FORMAT = "NAME:plume:LAT,LON,RADIUS,PEAK[,BACKGROUND] or NAME:field:LAT,LON,BASE,GRADIENT,BEARING, "
            + "optionally followed by @SYSID[+SYSID...], e.g. SMOKE:plume:40.4461,-7.3752,60,100@1+2";
    static final String VEHICLES_FORMAT = "SYSID[+SYSID...] or all, e.g. 2+3";

    private EquipmentText() {
    }

    /** {@code NAME:plume:...} or {@code NAME:field:...}, carried by every vehicle unless {@code @SYSIDS} follows. */
    static SimSensor sensor(String spec) {
        int at = spec.indexOf('@');
        String body = at < 0 ? spec : spec.substring(0, at);
        SysidSet vehicles = at < 0 ? SysidSet.ALL : vehicles(spec.substring(at + 1));
        String[] parts = body.split(":", -1);
        if (parts.length != 3) {
            throw new IllegalArgumentException("expected " + SENSOR_FORMAT);
        }
        double[] n = numbers(parts[2]);
        SimField field = switch (parts[1].strip().toLowerCase(Locale.ROOT)) {
            case "plume" -> {
                count(n, 4, 5, "plume", "LAT,LON,RADIUS,PEAK[,BACKGROUND]");
                yield new PlumeField(Position.fromDegrees(n[0], n[1], 0), n[2], n[3], n.length == 5 ? n[4] : 0);
            }
            case "field" -> {
                count(n, 5, 5, "field", "LAT,LON,BASE,GRADIENT,BEARING");
                yield new LinearField(Position.fromDegrees(n[0], n[1], 0), n[2], n[3], n[4]);
            }
            default -> throw new IllegalArgumentException("unknown kind '" + parts[1] + "': expected plume or field");
        };
        return new SimSensor(parts[0].strip(), field, vehicles);
    }

    /** {@code 2}, {@code 2+3} or {@code all}. */
    static SysidSet vehicles(String text) {
        if (text.strip().equalsIgnoreCase("all")) {
            return SysidSet.ALL;
        }
        List<Integer> ids = new ArrayList<>();
        for (String s : text.split("\\+", -1)) {
            try {
                ids.add(Integer.parseInt(s.strip()));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + s + "' is not a system id: expected " + VEHICLES_FORMAT);
            }
        }
        return SysidSet.of(ids);
    }

    private static double[] numbers(String text) {
        String[] parts = text.split(",", -1);
        double[] out = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            try {
                out[i] = Double.parseDouble(parts[i].strip());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + parts[i] + "' is not a number");
            }
        }
        return out;
    }

    private static void count(double[] n, int least, int most, String kind, String expected) {
        if (n.length < least || n.length > most) {
            throw new IllegalArgumentException("a " + kind + " takes " + expected + ", got " + n.length + " number(s)");
        }
    }
}
