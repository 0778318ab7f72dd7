package dolphin.cli;

import dolphin.mavlink.Autopilot;
import dolphin.sim.VehicleKind;
import java.util.Locale;
import java.util.stream.Collectors;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/**
 * The autopilot of simulated vehicles ({@code dolphin run --sim-autopilot}, {@code dolphin sim
 * --autopilot}): ArduPilot, or PX4 for the vehicle types it is simulated for.
 */
final class SimAutopilotOption {

    static final String HELP = "ardupilot or px4: the autopilot the simulated vehicles run; px4 with type copter, plane or "
            + "quadplane (a standard VTOL) (default: ${DEFAULT-VALUE}).";

    private SimAutopilotOption() {
    }

    /** {@code autopilot}, checked against the vehicle type; a usage error for a type it is not simulated for. */
    static Autopilot checked(CommandLine commandLine, String option, Autopilot autopilot, String typeOption, VehicleKind kind) {
        if (!kind.simulatedOn(autopilot)) {
            throw new ParameterException(commandLine, option + " " + autopilot.toString().toLowerCase(Locale.ROOT)
                    + " simulates " + VehicleKind.simulatedFor(autopilot).stream().map(k -> k.name().toLowerCase(Locale.ROOT))
                    .collect(Collectors.joining(", ")) + " only, got " + typeOption + " " + kind.name().toLowerCase(Locale.ROOT));
        }
        return autopilot;
    }
}
