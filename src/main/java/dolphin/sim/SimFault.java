package dolphin.sim;

import dolphin.mavlink.Autopilot;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * A fault to inject into simulated vehicles, written {@code KIND[=ARGS]@SECONDS[:SYSID]} (docs/mavlink.md,
 * "Faults"): e.g. {@code motor@60:1}, {@code takeover=15,loiter@90}, {@code stall@120}.
 *
 * @param kind what goes wrong
 * @param args its arguments as written, see {@link FaultKind#form()}
 * @param afterArmingSeconds when: seconds of clock time after the vehicle first arms, so at the same
 *        point of its flight whatever its warm-up and mission upload took
 * @param sysid the vehicle it happens to; 0: every vehicle of the fleet
 */
public record SimFault(FaultKind kind, List<String> args, double afterArmingSeconds, int sysid) {

    /** How a fault is written. */
    public static final String FORM = "KIND[=ARGS]@SECONDS[:SYSID]";

    public SimFault {
        args = args.stream().map(a -> a.strip().toLowerCase(Locale.ROOT)).toList();
        kind.recipe(args);
        if (!(afterArmingSeconds >= 0) || Double.isInfinite(afterArmingSeconds)) {
            throw new IllegalArgumentException("a fault comes a number of seconds after arming, 0 or more, got " + afterArmingSeconds);
        }
        if (sysid < 0 || sysid > 255) {
            throw new IllegalArgumentException("a system id must lie in 1..255, got " + sysid);
        }
    }

    /** The fault {@code text} describes; IllegalArgumentException saying what was expected when it is not one. */
    public static SimFault parse(String text) {
        String[] at = text.split("@", -1);
        if (at.length != 2) {
            throw new IllegalArgumentException("'" + text + "': expected " + FORM + ", e.g. motor@60:1 or takeover=15,loiter@90");
        }
        String[] when = at[1].split(":", -1);
        if (when.length > 2) {
            throw new IllegalArgumentException("'" + text + "': expected one :SYSID after @SECONDS");
        }
        int sysid = when.length == 2 ? sysid(when[1]) : 0;
        String[] what = at[0].split("=", 2);
        List<String> args = what.length == 2 ? Arrays.asList(what[1].split(",", -1)) : List.of();
        return new SimFault(FaultKind.parse(what[0]), args, FaultKind.seconds(when[0]), sysid);
    }

    private static int sysid(String text) {
        try {
            int id = Integer.parseInt(text.strip());
            if (id >= 1 && id <= 255) {
                return id;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException("'" + text + "' is not a system id in 1..255");
    }

    /** Whether it happens to vehicle {@code id}. */
    public boolean appliesTo(int id) {
        return sysid == 0 || sysid == id;
    }

    /** Whether vehicles of {@code vehicles} can have it: IllegalArgumentException saying why not. */
    public void checkFor(VehicleKind vehicles) {
        checkFor(vehicles, Autopilot.ARDUPILOT);
    }

    /** The same for vehicles that run {@code autopilot}, whose modes a takeover names. */
    public void checkFor(VehicleKind vehicles, Autopilot autopilot) {
        start(vehicles, SimAutopilot.of(autopilot).firmware(vehicles));
    }

    /** The fault on a vehicle of kind {@code vehicles} running {@code firmware}, waiting for its time. */
    Fault start(VehicleKind vehicles, Firmware firmware) {
        if (!kind.simulatedOn(firmware)) {
            throw new IllegalArgumentException(kind.label() + " is not simulated on a " + vehicles.name().toLowerCase(Locale.ROOT)
                    + ", only on " + kind.kindsSimulated());
        }
        return kind.recipe(args).make(firmware);
    }

    /** As written: {@code takeover=15,loiter@90:2}. */
    @Override
    public String toString() {
        String seconds = afterArmingSeconds == Math.rint(afterArmingSeconds) ? Long.toString((long) afterArmingSeconds)
                : Double.toString(afterArmingSeconds);
        return kind.label() + (args.isEmpty() ? "" : "=" + String.join(",", args)) + "@" + seconds + (sysid == 0 ? "" : ":" + sysid);
    }
}
