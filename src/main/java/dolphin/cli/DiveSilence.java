package dolphin.cli;

import dolphin.sim.VehicleKind;
import java.util.Locale;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/**
 * The dive silence of simulated subs ({@code dolphin run --sim-dive-silence}, {@code dolphin sim
 * --dive-silence}): a depth in metres, 0 or more, for a fleet of subs only.
 */
final class DiveSilence {

    private DiveSilence() {
    }

    /** The depth {@code given} with {@code option}; infinite (never silent) when not given; a usage error when it makes no sense. */
    static double metres(CommandLine commandLine, String option, Double given, String typeOption, VehicleKind kind) {
        if (given == null) {
            return Double.POSITIVE_INFINITY;
        }
        if (kind != VehicleKind.SUB) {
            throw new ParameterException(commandLine, option + " needs " + typeOption + " sub: only a sub dives, got "
                    + typeOption + " " + kind.name().toLowerCase(Locale.ROOT));
        }
        if (!(given >= 0) || given.isInfinite()) {
            throw new ParameterException(commandLine, option + " must be a depth in metres, 0 or more, got " + given);
        }
        return given;
    }
}
