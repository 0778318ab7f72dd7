package dolphin.cli;

import dolphin.core.Clock;
import dolphin.core.Position;
import dolphin.core.SystemClock;
import dolphin.dsl.Engine;
import dolphin.dsl.ScriptResult;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.Forwarder;
import dolphin.mavlink.LinkTimeouts;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkConfig;
import dolphin.platform.MAVLinkPlatform;
import dolphin.mavlink.codec.SigningKey;
import dolphin.mavlink.link.LinkUrl;
import dolphin.mission.flight.MissionExecutorConfig;
import dolphin.mission.flight.MissionService;
import dolphin.mission.transfer.MissionTransferConfig;
import dolphin.mission.transfer.TransferPath;
import dolphin.sensor.FleetFile;
import dolphin.sensor.SensorService;
import dolphin.sim.FaultModel;
import dolphin.sim.SimFault;
import dolphin.sim.SimFleet;
import dolphin.sim.SimOptions;
import dolphin.sim.VehicleKind;
import dolphin.web.WebAddress;
import dolphin.web.WebView;
import dolphin.web.WebViewException;
import java.io.IOException;
import java.io.PrintWriter;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code dolphin run SCRIPT}: runs a script against MAVLink vehicles, real or simulated. */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = "Runs a Dolphin script against MAVLink vehicles. Exit 0 when it completes, 1 on a script or "
                + "task error, 2 on a usage error.")
final class RunCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Parameters(paramLabel = "SCRIPT", description = "The .dolphin script to run.")
    private Path script;

    @Option(names = "--link", paramLabel = "URL", converter = Converters.LinkUrlConverter.class,
            description = "A link to vehicles: udpin:HOST:PORT, udpout:HOST:PORT, tcp:HOST:PORT or serial:DEVICE:BAUD. "
                    + "Repeatable. Default: " + MAVLinkConfig.DEFAULT_LINK + " (or a private port with --sim).")
    private List<LinkUrl> links = new ArrayList<>();

    @Option(names = "--sim", paramLabel = "N", description = "Start N simulated vehicles in this process, on loopback.")
    private int sim;

    @Option(names = "--sim-type", paramLabel = "TYPE", converter = Converters.VehicleKindConverter.class, defaultValue = "copter",
            description = "copter, plane, rover, boat, sub, quadplane (vtol) or heli (helicopter) (default: ${DEFAULT-VALUE}).")
    private VehicleKind simType;

    @Option(names = "--sim-autopilot", paramLabel = "AUTOPILOT", converter = Converters.AutopilotConverter.class,
            defaultValue = "ardupilot", description = SimAutopilotOption.HELP)
    private Autopilot simAutopilot;

    @Option(names = "--sim-home", paramLabel = "LAT,LON[,ALT]", converter = Converters.Home.class,
            description = "With --sim: home of the first simulated vehicle, the others 10 m apart to the east; ALT in metres "
                    + "above sea level, 0 if left out (default: 40.444233,-7.375234,820).")
    private Position simHome;

    @Option(names = "--sim-dive-silence", paramLabel = "METRES",
            description = "With --sim and --sim-type sub: a sub deeper than this below the surface sends and hears nothing, "
                    + "as its radio under water, until it is shallower again (default: always heard).")
    private Double simDiveSilence;

    @Option(names = "--sim-no-ftp",
            description = "With --sim: simulated vehicles without MAVLink FTP, as firmware built without it: "
                    + "FILE_TRANSFER_PROTOCOL gets no answer and AUTOPILOT_VERSION has no FTP capability.")
    private boolean simNoFtp;

    @Option(names = "--speedup", paramLabel = "X", defaultValue = "1",
            description = "With --sim: run time X times faster than real time (default: ${DEFAULT-VALUE}).")
    private double speedup;

    @Mixin
    LinkFaultOptions faults;

    @Option(names = "--sim-sensor", paramLabel = "SPEC", description = "With --sim: " + EquipmentOptions.SENSOR_HELP)
    private List<String> simSensors = new ArrayList<>();

    @Option(names = "--sim-camera", paramLabel = "SYSIDS", description = "With --sim: " + EquipmentOptions.CAMERA_HELP)
    private String simCameras;

    @Option(names = "--sim-config", paramLabel = "FILE", description = "With --sim: " + EquipmentOptions.CONFIG_HELP)
    private Path simConfig;

    @Option(names = "--sim-fault", paramLabel = SimFault.FORM, converter = FaultOptions.Converter.class,
            description = "With --sim: " + FaultOptions.HELP)
    private List<SimFault> simFaults = new ArrayList<>();

    @Option(names = "--tlog", paramLabel = "FILE", description = "Write every MAVLink frame in and out to a .tlog file.")
    private Path tlog;

    @Option(names = "--sysid", paramLabel = "N", defaultValue = "" + MAVLinkConfig.DEFAULT_SYSID,
            description = "This ground station's system id (default: ${DEFAULT-VALUE}).")
    private int sysid;

    @Option(names = "--signing-key", paramLabel = "FILE", converter = Converters.SigningKeyConverter.class,
            description = "Sign frames and accept only signed ones: a file with 64 hex digits or a passphrase.")
    private SigningKey key;

    @Option(names = "--forward", paramLabel = "URL", converter = Converters.LinkUrlConverter.class,
            description = "Relay the vehicles' traffic to a viewer (QGroundControl, MAVProxy) and its commands back, "
                    + "e.g. udpout:127.0.0.1:14550. Repeatable.")
    private List<LinkUrl> forwards = new ArrayList<>();

    @Option(names = "--command-attempts", paramLabel = "N", defaultValue = "" + MAVLinkConfig.DEFAULT_COMMAND_ATTEMPTS,
            description = "Sends of a command, one second apart, before it fails without COMMAND_ACK; more for a lossy "
                    + "radio link (default: ${DEFAULT-VALUE}).")
    private int commandAttempts;

    @Option(names = "--transfer-min-timeout", paramLabel = "MS", defaultValue = "50",
            description = "Mission transfers: the shortest wait for the vehicle's answer before sending again, in "
                    + "milliseconds; the wait follows the link's measured round trip (default: ${DEFAULT-VALUE}).")
    private long transferMinTimeoutMillis;

    @Option(names = "--transfer-max-timeout", paramLabel = "MS", defaultValue = "1500",
            description = "Mission transfers: the longest wait before sending again, in milliseconds, also the wait before "
                    + "the round trip is measured (default: ${DEFAULT-VALUE}).")
    private long transferMaxTimeoutMillis;

    @Option(names = "--transfer-give-up", paramLabel = "S", defaultValue = "10",
            description = "Mission transfers: seconds without progress before a transfer fails (default: ${DEFAULT-VALUE}; "
                    + "ArduPilot itself cancels an upload after 8 s without an item).")
    private double transferGiveUpSeconds;

    @Option(names = "--transfer-path", paramLabel = "PATH", converter = Converters.TransferPathConverter.class,
            defaultValue = "auto",
            description = "Mission transfers: ftp (the whole list as one file over MAVLink FTP), items (the mission "
                    + "protocol, item by item) or auto (FTP where the vehicle offers it, else items) "
                    + "(default: ${DEFAULT-VALUE}).")
    private TransferPath transferPath;

    @Option(names = "--ready-timeout", paramLabel = "SECONDS", defaultValue = "180",
            description = "How long a mission waits for its vehicle to become ready (a position estimate, a home, pre-arm "
                    + "checks passing) before it fails quoting the vehicle's PreArm text (default: ${DEFAULT-VALUE}).")
    private long readyTimeoutSeconds;

    @Option(names = "--stall-limit", paramLabel = "SECONDS", defaultValue = "60",
            description = "How long a vehicle may make no progress toward its mission item, or its landing, before the "
                    + "mission fails; a line warns after a third of it, at most 20 s; a mission's stallLimit overrides it "
                    + "(default: ${DEFAULT-VALUE}).")
    private long stallLimitSeconds;

    @Option(names = "--takeover-timeout", paramLabel = "SECONDS", defaultValue = "120",
            description = "How long a pilot or another ground station may hold a vehicle out of AUTO (LOITER, HOLD, ...) "
                    + "before its mission fails; the mission is paused until then; a mission's takeoverTimeout overrides it "
                    + "(default: ${DEFAULT-VALUE}).")
    private long takeoverTimeoutSeconds;

    @Option(names = "--fleet", paramLabel = "FILE", converter = Converters.FleetFileConverter.class,
            description = "A fleet file: by system id, the vehicles' names, Dolphin types, payloads and sensors, for vehicles "
                    + "that do not announce them (docs/sensors.md).")
    private FleetFile fleetFile = FleetFile.NONE;

    @Option(names = "--web", paramLabel = "[HOST:]PORT", converter = Converters.Web.class,
            description = "Serve a live view of the run (map, task trees, event log) at http://HOST:PORT/; HOST defaults "
                    + "to 127.0.0.1 (loopback only); another address needs the token printed at start. Port 0 takes a free port.")
    private WebAddress web;

    @Option(names = "--web-tiles", paramLabel = "URL",
            description = "Map tiles for --web, e.g. https://tile.openstreetmap.org/{z}/{x}/{y}.png (default: none, a plain "
                    + "background with a scale; the vehicles, tracks and missions are drawn either way).")
    private String webTiles;

    /** How the vehicles' status is shown. */
    enum StatusMode { auto, live, plain }

    @Option(names = "--status", paramLabel = "MODE", defaultValue = "auto",
            description = "live: a table of the vehicles redrawn in place; plain: timestamped lines, one more for a vehicle "
                    + "when its mode, arming or task changes; auto: live on a terminal, else plain (default: ${DEFAULT-VALUE}).")
    private StatusMode status;

    /** Rows of the live table before the rest of the fleet is summed up in one row. */
    static final int LIVE_ROWS = 20;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        validate();
        MAVLinkConfig config = mavlinkConfig();
        MissionTransferConfig transfers = transferConfig();
        MissionExecutorConfig executor = executorConfig();
        FaultModel faultModel = faultModel();
        String source = Main.readScript("run", script, err);
        if (source == null) {
            return Main.USAGE;
        }
        Clock clock = sim > 0 ? new SystemClock(speedup) : SystemClock.REAL;
        MAVLinkCommunications comms = new MAVLinkCommunications(config, clock);
        MissionService missions = MissionService.of(comms);
        missions.setTransferConfig(transfers);
        missions.setExecutorConfig(executor);
        SensorService.of(comms).useFleet(fleetFile);
        Forwarder forwarder = new Forwarder(comms, forwards);
        try {
            comms.start();
            forwarder.start();
        } catch (IOException e) {
            comms.close();
            err.println("dolphin run: " + e.getMessage());
            return Main.USAGE;
        }
        SimFleet fleet = null;
        try (comms; forwarder) {
            if (sim > 0) {
                fleet = startFleet(comms, clock, faultModel);
            }
            Engine engine = new Engine(new MAVLinkPlatform(comms), clock);
            Screen screen = screen(out, clock);
            try (AutoCloseable view = startWebView(comms, engine, out, err);
                 RunConsole console = new RunConsole(screen, comms::nodes, SystemClock.REAL);
                 AutoCloseable logs = screen instanceof LiveScreen live ? TerminalErr.captureIfShared(live::above) : () -> { }) {
                engine.addListener(console);
                console.start();
                ScriptResult result = engine.run(source, script.toString()).await();
                if (result.error() != null) {
                    err.println(result.error());
                }
                out.flush();
                return result.exitCode();
            }
        } finally {
            if (fleet != null) {
                fleet.close();
            }
        }
    }

    /**
     * The web view when asked for; when it cannot start (port in use, unknown host) the run goes on
     * without it, as a flight should not wait on a viewer.
     */
    private AutoCloseable startWebView(MAVLinkCommunications comms, Engine engine, PrintWriter out, PrintWriter err) {
        if (web == null) {
            return () -> { };
        }
        try {
            WebView view = WebView.start(new WebView.Settings(web, webTiles), comms, engine, SystemClock.REAL);
            out.println("web view: " + view.address());
            out.flush();
            return view;
        } catch (WebViewException e) {
            err.println("dolphin run: web view not started: " + e.getMessage() + "; the run goes on without it");
            err.flush();
            return () -> { };
        }
    }

    /** One listening port for a real fleet; private loopback ports for the simulated one, 255 vehicles each. */
    private List<LinkUrl> defaultLinks() {
        if (sim == 0) {
            return List.of(LinkUrl.parse(MAVLinkConfig.DEFAULT_LINK));
        }
        return Collections.nCopies((sim + 254) / 255, LinkUrl.parse("udpin:127.0.0.1:0"));
    }

    private Screen screen(PrintWriter out, Clock clock) {
        boolean live = status == StatusMode.live || status == StatusMode.auto && System.console() != null
                && System.getenv("TERM") != null && !"dumb".equals(System.getenv("TERM"));
        return live ? new LiveScreen(out, RunConsole.stamp(clock), LIVE_ROWS) : new PlainScreen(out, RunConsole.stamp(clock));
    }

    private void validate() {
        if (sim < 0) {
            throw new ParameterException(spec.commandLine(), "--sim must be a positive number of vehicles, got " + sim);
        }
        Main.checkSpeedup(spec, speedup);
        if (speedup != 1 && sim == 0) {
            throw new ParameterException(spec.commandLine(), "--speedup needs --sim: real vehicles run in real time");
        }
        needsSim(EquipmentOptions.OptionNames.RUN.all(), "only simulated vehicles carry simulated sensors and cameras");
        needsSim(List.of("--sim-home", "--sim-dive-silence", "--sim-no-ftp", "--sim-fault", "--sim-autopilot"), "it sets up the simulated fleet");
        if (webTiles != null && web == null) {
            throw new ParameterException(spec.commandLine(), "--web-tiles needs --web");
        }
        if (webTiles != null && !(webTiles.contains("{z}") && webTiles.contains("{x}") && webTiles.contains("{y}"))) {
            throw new ParameterException(spec.commandLine(), "--web-tiles '" + webTiles
                    + "': expected a tile URL with {z}, {x} and {y}, e.g. https://tile.openstreetmap.org/{z}/{x}/{y}.png");
        }
        if (sysid < 1 || sysid > 255) {
            throw new ParameterException(spec.commandLine(), "--sysid must be in 1..255, got " + sysid);
        }
    }

    /** Without --sim, the first of these options given is a usage error saying why it needs --sim. */
    private void needsSim(List<String> options, String why) {
        if (sim > 0) {
            return;
        }
        for (String option : options) {
            if (spec.commandLine().getParseResult().hasMatchedOption(option)) {
                throw new ParameterException(spec.commandLine(), option + " needs --sim: " + why);
            }
        }
    }

    /** The ground station's ids, links and command retries from the options. */
    MAVLinkConfig mavlinkConfig() {
        if (commandAttempts < 1) {
            throw new ParameterException(spec.commandLine(), "--command-attempts must be at least 1, got " + commandAttempts);
        }
        return MAVLinkConfig.of(links.isEmpty() ? defaultLinks() : links)
                .withSysid(sysid).withSigningKey(key).withTlog(tlog).withCommandAttempts(commandAttempts);
    }

    /** The timeouts and path of every mission transfer, from the options. */
    MissionTransferConfig transferConfig() {
        if (transferMinTimeoutMillis <= 0) {
            throw new ParameterException(spec.commandLine(),
                    "--transfer-min-timeout must be a positive number of milliseconds, got " + transferMinTimeoutMillis);
        }
        if (transferMaxTimeoutMillis < transferMinTimeoutMillis) {
            throw new ParameterException(spec.commandLine(), "--transfer-max-timeout (" + transferMaxTimeoutMillis
                    + " ms) must be at least --transfer-min-timeout (" + transferMinTimeoutMillis + " ms)");
        }
        long giveUpMillis = Math.round(transferGiveUpSeconds * 1000);
        if (!(giveUpMillis >= transferMaxTimeoutMillis)) {
            throw new ParameterException(spec.commandLine(), "--transfer-give-up (" + transferGiveUpSeconds
                    + " s) must be at least --transfer-max-timeout (" + transferMaxTimeoutMillis + " ms)");
        }
        return new MissionTransferConfig(new LinkTimeouts(Duration.ofMillis(transferMinTimeoutMillis),
                Duration.ofMillis(transferMaxTimeoutMillis), Duration.ofMillis(giveUpMillis)), transferPath);
    }

    /** The mission executor's deadlines, from the options. */
    MissionExecutorConfig executorConfig() {
        return MissionExecutorConfig.DEFAULT.withPrepare(positiveSeconds("--ready-timeout", readyTimeoutSeconds))
                .withStallLimit(positiveSeconds("--stall-limit", stallLimitSeconds))
                .withTakeoverTimeout(positiveSeconds("--takeover-timeout", takeoverTimeoutSeconds));
    }

    private Duration positiveSeconds(String option, long seconds) {
        if (seconds <= 0) {
            throw new ParameterException(spec.commandLine(), option + " must be a positive number of seconds, got " + seconds);
        }
        return Duration.ofSeconds(seconds);
    }

    /** The simulated link's faults; refused without --sim, where there is no simulated link to apply them to. */
    FaultModel faultModel() {
        List<String> given = faults.given();
        if (sim == 0 && !given.isEmpty()) {
            throw new ParameterException(spec.commandLine(),
                    given.get(0) + " needs --sim: link faults are simulated, between the simulated vehicles and this ground station");
        }
        return faults.model();
    }

    /** The simulated fleet sends to every listening link, split over them in blocks. */
    private SimFleet startFleet(MAVLinkCommunications comms, Clock clock, FaultModel faultModel) throws IOException {
        List<InetSocketAddress> ports = comms.links().stream().filter(l -> l.url().kind() == LinkUrl.Transport.UDPIN)
                .map(l -> new InetSocketAddress("127.0.0.1", l.localPort())).toList();
        if (ports.isEmpty()) {
            throw new ParameterException(spec.commandLine(), "--sim needs a udpin link for the simulated vehicles to send to");
        }
        SimFleet fleet = new SimFleet(fleetConfig(ports, faultModel), clock);
        fleet.start();
        return fleet;
    }

    /** The in-process fleet the options describe, sending to these ground station ports. */
    SimFleet.Config fleetConfig(List<InetSocketAddress> ports, FaultModel faultModel) {
        SimOptions options = SimOptions.DEFAULT.withDiveSilence(
                DiveSilence.metres(spec.commandLine(), "--sim-dive-silence", simDiveSilence, "--sim-type", simType));
        if (simNoFtp) {
            options = options.withoutFtp();
        }
        options = options.withAutopilot(SimAutopilotOption.checked(spec.commandLine(), "--sim-autopilot", simAutopilot,
                "--sim-type", simType));
        SimFleet.Config config;
        try {
            config = SimFleet.Config.of(sim, simType, ports).withSigningKey(key).withFaults(faultModel).withOptions(options);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "--sim " + sim + ": " + e.getMessage());
        }
        if (simHome != null) {
            config = config.withHome(simHome);
        }
        config = config.withEquipment(new EquipmentOptions(EquipmentOptions.OptionNames.RUN, simSensors, simCameras, simConfig)
                .equipment(spec.commandLine(), config.firstSysid(), config.highestSysid()));
        return FaultOptions.inject(spec.commandLine(), "--sim-fault", simFaults, config);
    }
}
