package dolphin.cli;

import dolphin.core.Clock;
import dolphin.core.SystemClock;
import dolphin.core.TaskEvent;
import dolphin.dsl.Engine;
import dolphin.dsl.EngineListener;
import dolphin.dsl.ScriptResult;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkConfig;
import dolphin.mavlink.MAVLinkPlatform;
import dolphin.mavlink.codec.SigningKey;
import dolphin.mavlink.link.LinkUrl;
import dolphin.sim.SimFleet;
import dolphin.sim.VehicleKind;
import java.io.IOException;
import java.io.PrintWriter;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
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

    @Option(names = "--link", paramLabel = "URL", converter = Converters.Link.class,
            description = "A link to vehicles: udpin:HOST:PORT, udpout:HOST:PORT, tcp:HOST:PORT or serial:DEVICE:BAUD. "
                    + "Repeatable. Default: " + MAVLinkConfig.DEFAULT_LINK + " (or a private port with --sim).")
    private List<LinkUrl> links = new ArrayList<>();

    @Option(names = "--sim", paramLabel = "N", description = "Start N simulated vehicles in this process, on loopback.")
    private int sim;

    @Option(names = "--sim-type", paramLabel = "TYPE", converter = Converters.Kind.class, defaultValue = "copter",
            description = "copter or plane (default: ${DEFAULT-VALUE}).")
    private VehicleKind simType;

    @Option(names = "--speedup", paramLabel = "X", defaultValue = "1",
            description = "With --sim: run time X times faster than real time (default: ${DEFAULT-VALUE}).")
    private double speedup;

    @Option(names = "--tlog", paramLabel = "FILE", description = "Write every MAVLink frame in and out to a .tlog file.")
    private Path tlog;

    @Option(names = "--sysid", paramLabel = "N", defaultValue = "" + MAVLinkConfig.DEFAULT_SYSID,
            description = "This ground station's system id (default: ${DEFAULT-VALUE}).")
    private int sysid;

    @Option(names = "--signing-key", paramLabel = "FILE", converter = Converters.Key.class,
            description = "Sign frames and accept only signed ones: a file with 64 hex digits or a passphrase.")
    private SigningKey key;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        validate();
        String source = Main.readScript("run", script, err);
        if (source == null) {
            return Main.USAGE;
        }
        Clock clock = sim > 0 ? new SystemClock(speedup) : SystemClock.REAL;
        List<LinkUrl> urls = !links.isEmpty() ? links : List.of(LinkUrl.parse(sim > 0 ? "udpin:127.0.0.1:0" : MAVLinkConfig.DEFAULT_LINK));
        MAVLinkConfig config = MAVLinkConfig.of(urls).withSysid(sysid).withSigningKey(key).withTlog(tlog);
        MAVLinkCommunications comms = new MAVLinkCommunications(config, clock);
        try {
            comms.start();
        } catch (IOException e) {
            err.println("dolphin run: " + e.getMessage());
            return Main.USAGE;
        }
        SimFleet fleet = null;
        try (comms) {
            if (sim > 0) {
                fleet = startFleet(comms, clock);
            }
            Engine engine = new Engine(new MAVLinkPlatform(comms), clock);
            engine.addListener(new Console(out, clock));
            ScriptResult result = engine.run(source, script.toString()).await();
            if (result.error() != null) {
                err.println(result.error());
            }
            out.flush();
            return result.exitCode();
        } finally {
            if (fleet != null) {
                fleet.close();
            }
        }
    }

    private void validate() {
        if (sim < 0) {
            throw new ParameterException(spec.commandLine(), "--sim must be a positive number of vehicles, got " + sim);
        }
        Main.checkSpeedup(spec, speedup);
        if (speedup != 1 && sim == 0) {
            throw new ParameterException(spec.commandLine(), "--speedup needs --sim: real vehicles run in real time");
        }
        if (sysid < 1 || sysid > 255) {
            throw new ParameterException(spec.commandLine(), "--sysid must be in 1..255, got " + sysid);
        }
    }

    private SimFleet startFleet(MAVLinkCommunications comms, Clock clock) throws IOException {
        int port = comms.links().get(0).localPort();
        if (port <= 0) {
            throw new ParameterException(spec.commandLine(), "--sim needs the first --link to be a udpin link");
        }
        SimFleet.Config config = SimFleet.Config.of(sim, simType, new InetSocketAddress("127.0.0.1", port)).withSigningKey(key);
        SimFleet fleet = new SimFleet(config, clock);
        fleet.start();
        return fleet;
    }

    /** Plain timestamped lines: program messages and the platform tasks' events. */
    private static final class Console implements EngineListener {
        private final PrintWriter out;
        private final Clock clock;
        private final double start;

        Console(PrintWriter out, Clock clock) {
            this.out = out;
            this.clock = clock;
            this.start = clock.seconds();
        }

        @Override
        public void message(String text) {
            line(text);
        }

        @Override
        public void taskEvent(TaskEvent event) {
            if (event.isPlatformTask()) {
                line("task " + event.task().getId() + " " + event.kind().name().toLowerCase(java.util.Locale.ROOT)
                        + (event.vehicles().isEmpty() ? "" : " on vehicle " + String.join(",", event.vehicles()))
                        + (event.kind() == TaskEvent.Kind.COMPLETED ? ": " + event.state() : ""));
            }
        }

        @Override
        public void scriptFinished(String name, ScriptResult result) {
            line(name + ": " + result.outcome().name().toLowerCase(java.util.Locale.ROOT)
                    + (result.message() == null ? "" : " (" + result.message() + ")"));
        }

        private synchronized void line(String text) {
            out.printf(java.util.Locale.ROOT, "[%8.1f s] %s%n", clock.seconds() - start, text);
            out.flush();
        }
    }
}
