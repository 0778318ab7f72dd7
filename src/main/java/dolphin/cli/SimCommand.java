package dolphin.cli;

import dolphin.core.Position;
import dolphin.core.SystemClock;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.codec.SigningKey;
import dolphin.mavlink.link.LinkUrl;
import dolphin.sim.FaultModel;
import dolphin.sim.SimEquipment;
import dolphin.sim.SimFault;
import dolphin.sim.SimFleet;
import dolphin.sim.SimOptions;
import dolphin.sim.VehicleKind;
import java.io.PrintWriter;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code dolphin sim}: a fleet of simulated ArduPilot vehicles, for a separate {@code dolphin run} or another ground station. */
@Command(name = "sim", mixinStandardHelpOptions = true,
        description = "Simulates ArduPilot vehicles that send MAVLink 2 over UDP to a ground station, like SITL with "
                + "--serial0 udpclient:HOST:PORT. Runs until interrupted or for --duration.")
final class SimCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Option(names = "--count", paramLabel = "N", defaultValue = "1", description = "How many vehicles (default: ${DEFAULT-VALUE}).")
    private int count;

    @Option(names = "--link", paramLabel = "URL", converter = Converters.LinkUrlConverter.class,
            description = "Where the vehicles send: udpout:HOST:PORT, repeatable (vehicles are split over the links in blocks; over 255 vehicles need several links, and system ids start again on each). "
                    + "Default: udpout:127.0.0.1:14559.")
    private List<LinkUrl> links = new ArrayList<>();

    @Option(names = "--type", paramLabel = "TYPE", converter = Converters.VehicleKindConverter.class, defaultValue = "copter",
            description = "copter, plane, rover, boat, sub, quadplane (vtol) or heli (helicopter) (default: ${DEFAULT-VALUE}).")
    private VehicleKind type;

    @Option(names = "--autopilot", paramLabel = "AUTOPILOT", converter = Converters.AutopilotConverter.class,
            defaultValue = "ardupilot", description = SimAutopilotOption.HELP)
    private Autopilot autopilot;

    @Option(names = "--home", paramLabel = "LAT,LON[,ALT]", converter = Converters.Home.class,
            description = "Home of the first vehicle, the others 10 m apart to the east; ALT in metres above sea level, 0 if "
                    + "left out (default: 40.444233,-7.375234,820).")
    private Position home;

    @Option(names = "--dive-silence", paramLabel = "METRES",
            description = "With --type sub: a sub deeper than this below the surface sends and hears nothing, as its radio "
                    + "under water, until it is shallower again (default: always heard).")
    private Double diveSilence;

    @Option(names = "--no-ftp",
            description = "Vehicles without MAVLink FTP, as firmware built without it: FILE_TRANSFER_PROTOCOL gets no answer "
                    + "and AUTOPILOT_VERSION has no FTP capability, so ground stations transfer missions item by item.")
    private boolean noFtp;

    @Option(names = "--first-sysid", paramLabel = "N", defaultValue = "1", description = "System id of the first vehicle.")
    private int firstSysid;

    @Option(names = "--speedup", paramLabel = "X", defaultValue = "1", description = "Run X times faster than real time.")
    private double speedup;

    @Option(names = "--warmup", paramLabel = "SECONDS", defaultValue = "0",
            description = "No position estimate this long after start, as ArduPilot while its EKF settles (SITL: about 41 s): "
                    + "position 0,0, no home, DO_SET_HOME failing, \"PreArm: Need Position Estimate\" (default: ${DEFAULT-VALUE}).")
    private double warmup;

    @Option(names = "--drain", paramLabel = "PERCENT_PER_MINUTE", defaultValue = "14",
            description = "Battery use while armed (default: ${DEFAULT-VALUE}, about ArduCopter SITL's).")
    private double drain;

    @Option(names = "--duration", paramLabel = "SECONDS", description = "Stop after this much simulated time.")
    private Double duration;

    @Option(names = "--signing-key", paramLabel = "FILE", converter = Converters.SigningKeyConverter.class,
            description = "Sign frames and accept only signed ones: a file with 64 hex digits or a passphrase.")
    private SigningKey key;

    @Mixin
    LinkFaultOptions faults;

    @Option(names = "--fault", paramLabel = SimFault.FORM, converter = FaultOptions.Converter.class, description = FaultOptions.HELP)
    private List<SimFault> injected = new ArrayList<>();

    @Option(names = "--sensor", paramLabel = "SPEC", description = EquipmentOptions.SENSOR_HELP)
    private List<String> sensors = new ArrayList<>();

    @Option(names = "--camera", paramLabel = "SYSIDS", description = EquipmentOptions.CAMERA_HELP)
    private String cameras;

    @Option(names = "--config", paramLabel = "FILE", description = EquipmentOptions.CONFIG_HELP)
    private Path equipmentFile;

    @Override
    public Integer call() throws Exception {
        Main.checkSpeedup(spec, speedup);
        SimFleet.Config config = fleetConfig();
        List<InetSocketAddress> gcs = config.gcs();
        SystemClock clock = new SystemClock(speedup);
        PrintWriter out = spec.commandLine().getOut();
        try (SimFleet fleet = new SimFleet(config, clock)) {
            fleet.start();
            out.printf("simulating %d %s%s(s), system ids %d..%d%s, sending to %s%s%n", count, autopilot == Autopilot.PX4 ? "PX4 " : "",
                    type.name().toLowerCase(java.util.Locale.ROOT),
                    firstSysid, config.highestSysid(),
                    gcs.size() > 1 ? " (" + config.perLink() + " per link)" : "", gcs, speedup != 1 ? " at " + speedup + "x" : "");
            if (!config.options().faults().isEmpty()) {
                out.printf("faults, at seconds after a vehicle first arms: %s%n", config.options().faults().stream()
                        .map(SimFault::toString).collect(Collectors.joining(", ")));
            }
            out.flush();
            Runtime.getRuntime().addShutdownHook(new Thread(fleet::close));
            if (duration == null) {
                Thread.currentThread().join();
            } else {
                clock.sleep(Duration.ofNanos((long) (duration * 1e9)));
            }
        }
        return 0;
    }

    /** The fleet the options describe; a bad value is a usage error. */
    SimFleet.Config fleetConfig() {
        if (count < 1) {
            throw new ParameterException(spec.commandLine(), "--count must be at least 1, got " + count);
        }
        FaultModel faultModel = faults.model();
        List<InetSocketAddress> gcs = new ArrayList<>();
        for (LinkUrl url : links.isEmpty() ? List.of(LinkUrl.parse("udpout:127.0.0.1:14559")) : links) {
            if (url.kind() != LinkUrl.Transport.UDPOUT) {
                throw new ParameterException(spec.commandLine(), "--link for sim must be udpout:HOST:PORT, got " + url);
            }
            gcs.add(url.address());
        }
        SimOptions options = SimOptions.DEFAULT.withWarmup(warmup).withDrain(drain)
                .withDiveSilence(DiveSilence.metres(spec.commandLine(), "--dive-silence", diveSilence, "--type", type));
        if (noFtp) {
            options = options.withoutFtp();
        }
        options = options.withAutopilot(SimAutopilotOption.checked(spec.commandLine(), "--autopilot", autopilot, "--type", type));
        SimFleet.Config config;
        try {
            config = new SimFleet.Config(count, type, home != null ? home : SimFleet.Config.DEFAULT_HOME, SimFleet.Config.DEFAULT_SPACING,
                    firstSysid, gcs, options, key, faultModel, SimEquipment.NONE);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        config = config.withEquipment(new EquipmentOptions(EquipmentOptions.OptionNames.SIM, sensors, cameras, equipmentFile)
                .equipment(spec.commandLine(), firstSysid, config.highestSysid()));
        return FaultOptions.inject(spec.commandLine(), "--fault", injected, config);
    }
}
