package dolphin.cli;

import dolphin.sim.SimFault;
import dolphin.sim.SimFleet;
import dolphin.sim.SimOptions;
import dolphin.sim.SysidSet;
import java.util.List;
import java.util.Set;
import picocli.CommandLine;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.TypeConversionException;

/**
 * Faults injected into the simulated vehicles at a time ({@link SimFault}), from {@code dolphin sim
 * --fault} or {@code dolphin run --sim-fault}: a value not written as a fault is refused when the
 * option is read, a fault the fleet's vehicles cannot have, or for a system id not in the fleet, once
 * the fleet is known; each a usage error naming the option and what was expected.
 */
final class FaultOptions {

    static final String HELP = "A fault injected into the simulated vehicles, SECONDS of clock time after a vehicle first "
            + "arms, into vehicle SYSID only if given: motor[=N] (motor N, default 1, stops: a copter falls, a plane glides "
            + "down), gps (the GPS receiver falls silent: the EKF failsafe acts), takeover=SECONDS[,MODE] (a pilot on another "
            + "ground station holds it in MODE, by default LOITER, a rover's or boat's HOLD, a sub's POSHOLD, for SECONDS, then "
            + "sets AUTO), stall[=SECONDS] (it makes no progress in AUTO, for ever by default), reboot, outage=SECONDS (its "
            + "link silent both ways). E.g. motor@60:1. Repeatable.";

    private FaultOptions() {
    }

    /** A fault as written; picocli names the option and the value when it is not one. */
    static final class Converter implements ITypeConverter<SimFault> {
        @Override
        public SimFault convert(String value) {
            try {
                return SimFault.parse(value);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    /** {@code config} with the faults given with {@code option} injected, each checked against the fleet. */
    static SimFleet.Config inject(CommandLine cl, String option, List<SimFault> faults, SimFleet.Config config) {
        SimOptions options = config.options();
        for (SimFault fault : faults) {
            String where = option + " '" + fault + "'";
            try {
                fault.checkFor(config.kind(), config.options().autopilot());
            } catch (IllegalArgumentException e) {
                throw new ParameterException(cl, where + ": " + e.getMessage());
            }
            if (fault.sysid() != 0) {
                EquipmentOptions.inFleet(cl, where, SysidSet.of(Set.of(fault.sysid())), config.firstSysid(), config.highestSysid());
            }
            options = options.withFault(fault);
        }
        return config.withOptions(options);
    }
}
