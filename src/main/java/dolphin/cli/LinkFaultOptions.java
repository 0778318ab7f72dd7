package dolphin.cli;

import dolphin.sim.FaultModel;
import java.util.List;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * Link faults of the simulated fleet ({@link FaultModel}), shared by {@code dolphin sim} and
 * {@code dolphin run --sim}: every datagram between the simulated vehicles and the ground station,
 * both ways, may be lost, duplicated, delayed or overtaken.
 */
final class LinkFaultOptions {

    private static final List<String> NAMES = List.of("--loss", "--duplicate", "--delay", "--reorder", "--fault-seed");

    /** The command that has these options, so errors are its usage errors. */
    @Spec(Spec.Target.MIXEE)
    private CommandSpec spec;

    @Option(names = "--loss", paramLabel = "P", defaultValue = "0",
            description = "Simulated link: lose each datagram with probability P, 0 to 1 (default: ${DEFAULT-VALUE}).")
    private double loss;

    @Option(names = "--duplicate", paramLabel = "P", defaultValue = "0",
            description = "Simulated link: send each datagram twice with probability P, 0 to 1 (default: ${DEFAULT-VALUE}).")
    private double duplicate;

    @Option(names = "--delay", paramLabel = "MS", defaultValue = "0",
            description = "Simulated link: delay each datagram by MS milliseconds of the run's clock (default: ${DEFAULT-VALUE}).")
    private long delayMillis;

    @Option(names = "--reorder", paramLabel = "MS", defaultValue = "0",
            description = "Simulated link: delay each datagram by a random further 0 to MS milliseconds, so later ones "
                    + "can overtake it (default: ${DEFAULT-VALUE}).")
    private long reorderMillis;

    @Option(names = "--fault-seed", paramLabel = "N", defaultValue = "1",
            description = "Simulated link: the seed of the faults' random draws (default: ${DEFAULT-VALUE}).")
    private long seed;

    /** The fault model the options describe; a value out of range is a usage error naming the option. */
    FaultModel model() {
        checkProbability("--loss", loss);
        checkProbability("--duplicate", duplicate);
        checkMillis("--delay", delayMillis);
        checkMillis("--reorder", reorderMillis);
        return new FaultModel(loss, duplicate, delayMillis / 1000.0, reorderMillis / 1000.0, seed);
    }

    /** The fault options on the command line, for a command that accepts them only with a simulated fleet. */
    List<String> given() {
        return NAMES.stream().filter(spec.commandLine().getParseResult()::hasMatchedOption).toList();
    }

    private void checkProbability(String option, double p) {
        if (!(p >= 0 && p <= 1)) {
            throw new ParameterException(spec.commandLine(), option + " must be a probability from 0 to 1, got " + p);
        }
    }

    private void checkMillis(String option, long ms) {
        if (ms < 0) {
            throw new ParameterException(spec.commandLine(), option + " must be a number of milliseconds, 0 or more, got " + ms);
        }
    }
}
