package dolphin.sim;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.OptionalLong;
import java.util.stream.Collectors;

/**
 * The faults that can be injected into simulated vehicles (docs/mavlink.md, "Faults"), each with its
 * arguments ({@link #form()}): how it reads them, and which families have it ({@link Failures}).
 */
public enum FaultKind {

    /** {@code motor[=N]}: motor N (default 1) stops; a copter falls, a plane glides down. */
    MOTOR("motor[=N]") {
        @Override
        FaultRecipe recipe(List<String> args) {
            arguments(args, 0, 1);
            int motor = args.isEmpty() ? 1 : motorNumber(args.get(0));
            return firmware -> {
                Failures failures = firmware.failures();
                if (motor > failures.motors()) {
                    throw new IllegalArgumentException("motor " + motor + ": " + firmware.label() + " has "
                            + failures.motors() + (failures.motors() == 1 ? " motor" : " motors"));
                }
                return failures.powerLoss().orElseThrow().apply(motor);
            };
        }

        @Override
        boolean simulatedOn(Firmware firmware) {
            return firmware.failures().powerLoss().isPresent();
        }
    },

    /** {@code gps}: the GPS receiver falls silent; the EKF loses its position and the firmware's EKF failsafe acts. */
    GPS("gps") {
        @Override
        FaultRecipe recipe(List<String> args) {
            arguments(args, 0, 0);
            return firmware -> new GpsLoss(firmware.failures().ekfFailsafe().orElseThrow());
        }

        @Override
        boolean simulatedOn(Firmware firmware) {
            return firmware.failures().ekfFailsafe().isPresent();
        }
    },

    /** {@code takeover=SECONDS[,MODE]}: a pilot on another ground station sets MODE (the family's hold mode), then AUTO. */
    TAKEOVER("takeover=SECONDS[,MODE]") {
        @Override
        FaultRecipe recipe(List<String> args) {
            arguments(args, 1, 2);
            double seconds = seconds(args.get(0));
            String modeName = args.size() > 1 ? args.get(1) : null;
            return firmware -> new Takeover(modeName == null ? firmware.failures().takeoverMode() : mode(firmware, modeName), seconds);
        }
    },

    /** {@code stall[=SECONDS]}: in AUTO the vehicle makes no progress, for SECONDS or for ever. */
    STALL("stall[=SECONDS]") {
        @Override
        FaultRecipe recipe(List<String> args) {
            arguments(args, 0, 1);
            double seconds = args.isEmpty() ? Double.POSITIVE_INFINITY : seconds(args.get(0));
            return firmware -> new Stall(seconds);
        }
    },

    /** {@code reboot}: the autopilot reboots. */
    REBOOT("reboot") {
        @Override
        FaultRecipe recipe(List<String> args) {
            arguments(args, 0, 0);
            return firmware -> new Reboot();
        }
    },

    /** {@code outage=SECONDS}: the link is silent both ways for SECONDS. */
    OUTAGE("outage=SECONDS") {
        @Override
        FaultRecipe recipe(List<String> args) {
            arguments(args, 1, 1);
            double seconds = seconds(args.get(0));
            return firmware -> new Outage(seconds);
        }
    };

    private final String form;

    FaultKind(String form) {
        this.form = form;
    }

    /** What it is written as, with its arguments: {@code takeover=SECONDS[,MODE]}. */
    public String form() {
        return form;
    }

    /** Its name as written: {@code motor}. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The kind called {@code name}, in any case. */
    public static FaultKind parse(String name) {
        return Arrays.stream(values()).filter(k -> k.label().equals(name.strip().toLowerCase(Locale.ROOT))).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("unknown fault '" + name + "': expected "
                        + Arrays.stream(values()).map(FaultKind::label).collect(Collectors.joining(", "))));
    }

    /** How to make it from {@code args}; IllegalArgumentException when they are not what {@link #form()} says. */
    abstract FaultRecipe recipe(List<String> args);

    /** Whether vehicles of {@code firmware} have this fault. */
    boolean simulatedOn(Firmware firmware) {
        return true;
    }

    /** The vehicle kinds that have it, as written on the command line: "copter, plane". */
    String kindsSimulated() {
        return Arrays.stream(VehicleKind.values()).filter(k -> simulatedOn(k.firmware()))
                .map(k -> k.name().toLowerCase(Locale.ROOT)).collect(Collectors.joining(", "));
    }

    void arguments(List<String> args, int least, int most) {
        if (args.size() < least || args.size() > most) {
            throw new IllegalArgumentException(label() + (args.isEmpty() ? "" : "=" + String.join(",", args))
                    + ": expected " + form);
        }
    }

    static double seconds(String text) {
        double s;
        try {
            s = Double.parseDouble(text.strip());
        } catch (NumberFormatException e) {
            s = Double.NaN;
        }
        if (!(s >= 0) || Double.isInfinite(s)) {
            throw new IllegalArgumentException("'" + text + "' is not a number of seconds, 0 or more");
        }
        return s;
    }

    private static int motorNumber(String text) {
        try {
            int n = Integer.parseInt(text.strip());
            if (n >= 1) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException("'" + text + "' is not a motor number, 1 or more");
    }

    /** The takeover's mode: one of the family's, not AUTO, which is the mode it hands back. */
    private static int mode(Firmware firmware, String name) {
        OptionalLong mode = firmware.modes().number(name.strip());
        if (mode.isEmpty()) {
            throw new IllegalArgumentException(firmware.label() + " has no mode '" + name + "': expected one of "
                    + String.join(", ", firmware.modes().names().values()));
        }
        if (mode.getAsLong() == firmware.autoMode()) {
            throw new IllegalArgumentException("a takeover hands AUTO back, so its mode must be another one");
        }
        return (int) mode.getAsLong();
    }
}
