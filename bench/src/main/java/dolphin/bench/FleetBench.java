package dolphin.bench;

import com.MAVLink.common.msg_command_long;
import com.MAVLink.common.msg_sys_status;
import com.MAVLink.enums.MAV_CMD;
import dolphin.core.SystemClock;
import dolphin.dsl.Engine;
import dolphin.dsl.ScriptResult;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkConfig;
import dolphin.mavlink.MAVLinkNode;
import dolphin.platform.MAVLinkPlatform;
import dolphin.mavlink.codec.Frame;
import dolphin.mavlink.link.Link;
import dolphin.web.WebAddress;
import dolphin.web.WebView;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.TreeMap;
import java.util.function.BooleanSupplier;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Fleet scale: one `dolphin sim` process with N vehicles streaming at 4 Hz over N/250 links, and
 * this process as the runtime (MAVLinkCommunications, the engine, bench/fleet.dolphin) flying a
 * mission on every vehicle, each cut by its own battery guard. Measures the runtime's CPU and heap
 * per vehicle, and the reaction latency from the SYS_STATUS frame that crosses the threshold to
 * the DO_SET_MODE (RTL) frame sent to that vehicle, both seen on the communications thread.
 * The simulator process, which produces the same traffic, is the reference measured in the same run.
 *
 * <p>With {@code --web}, each size runs twice: without the web view, then with it and a page open in
 * a headless chromium (the same as a person watching), and the summary gives the ratios.
 *
 * <p>With {@code --flood RATE}, each size runs twice: without, then with every vehicle also sending RATE
 * NAMED_VALUE_FLOAT readings per second from a companion component (id 191), each of which wakes the
 * script's task tree; the summary gives the ratio of the reaction p99. One link only.
 *
 * <pre>FleetBench OUT_DIR SCRIPT JAVA CLASSPATH [--web | --flood RATE] SIZE...</pre>
 */
public final class FleetBench {

    static final int PER_LINK = 250;
    static final int THRESHOLD_PERCENT = 90;
    /** Battery use while armed: the 90 % threshold comes about 25 s after arming. */
    static final double DRAIN_PERCENT_PER_MINUTE = 24;
    static final Duration IDLE_WINDOW = Duration.ofSeconds(10);
    /** CPU is measured while every vehicle flies with its guard armed, before any cut. */
    static final Duration GUARDED_WINDOW = Duration.ofSeconds(8);

    private final Path out;
    private final String script;
    private final String java;
    private final String classpath;
    private final StringBuilder summary = new StringBuilder();
    private final List<Map<String, Object>> results = new ArrayList<>();

    FleetBench(Path out, String script, String java, String classpath) {
        this.out = out;
        this.script = script;
        this.java = java;
        this.classpath = classpath;
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 5) {
            System.err.println("usage: FleetBench OUT_DIR SCRIPT JAVA CLASSPATH [--web] SIZE...");
            System.exit(2);
        }
        Path out = Path.of(args[0]);
        Files.createDirectories(out);
        FleetBench bench = new FleetBench(out, Files.readString(Path.of(args[1])), args[2], args[3]);
        boolean web = args[4].equals("--web");
        int flood = args[4].equals("--flood") ? Integer.parseInt(args[5]) : 0;
        int failures = 0;
        for (int i = web ? 5 : flood > 0 ? 6 : 4; i < args.length; i++) {
            int n = Integer.parseInt(args[i]);
            failures += bench.run(n, false, 0);
            if (web) {
                failures += bench.run(n, true, 0);
                bench.compare(n);
            }
            if (flood > 0) {
                failures += bench.run(n, false, flood);
                bench.compareFlood(n, flood);
            }
        }
        bench.write();
        System.exit(failures == 0 ? 0 : 1);
    }

    /** Latency bookkeeping, on the communications thread; keys are "link/sysid". */
    private static final class Reactions implements MAVLinkCommunications.FrameObserver {
        final Map<String, Long> crossed = new ConcurrentHashMap<>();
        final Map<String, Long> reacted = new ConcurrentHashMap<>();

        @Override
        public void frame(boolean incoming, Link link, Frame frame) {
            long now = System.nanoTime();
            if (incoming && frame.msgid() == msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS
                    && frame.message() instanceof msg_sys_status s && s.battery_remaining >= 0 && s.battery_remaining < THRESHOLD_PERCENT) {
                crossed.putIfAbsent(link.index() + "/" + frame.sysid(), now);
            } else if (!incoming && frame.msgid() == msg_command_long.MAVLINK_MSG_ID_COMMAND_LONG
                    && frame.message() instanceof msg_command_long c && c.command == MAV_CMD.MAV_CMD_DO_SET_MODE) {
                String key = link.index() + "/" + c.target_system;
                if (crossed.containsKey(key)) {
                    reacted.putIfAbsent(key, now);
                }
            }
        }

        List<Double> latenciesMs() {
            List<Double> ms = new ArrayList<>();
            reacted.forEach((k, t) -> ms.add((t - crossed.get(k)) / 1e6));
            Collections.sort(ms);
            return ms;
        }
    }

    int run(int n, boolean web, int flood) throws Exception {
        int links = (n + PER_LINK - 1) / PER_LINK;
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        long heapBefore = usedHeap(memory);
        SystemClock clock = SystemClock.REAL;
        MAVLinkCommunications comms = new MAVLinkCommunications(
                MAVLinkConfig.of(Collections.nCopies(links, "udpin:127.0.0.1:0").toArray(String[]::new)), clock);
        comms.start();
        Reactions reactions = new Reactions();
        comms.addObserver(reactions);
        List<String> command = new ArrayList<>(List.of(java, "-cp", classpath, "-Dorg.slf4j.simpleLogger.defaultLogLevel=warn",
                "dolphin.cli.Main", "sim", "--count", "" + n, "--drain", "" + DRAIN_PERCENT_PER_MINUTE));
        for (Link l : comms.links()) {
            command.add("--link");
            command.add("udpout:127.0.0.1:" + l.localPort());
        }
        Process sim = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        int failures = 0;
        WebView view = null;
        Process browser = null;
        ReadingFlood flooder = null;
        try {
            check(waitFor(Duration.ofSeconds(120), () -> comms.nodes().size() == n
                    && comms.nodes().stream().allMatch(v -> v.state().batteryPercent() >= 0 && v.state().position() != null)),
                    n + " vehicles discovered with telemetry");
            long heapVehicles = usedHeap(memory) - heapBefore;

            Engine engine = new Engine(new MAVLinkPlatform(comms), clock);
            if (web) {
                view = WebView.start(new WebView.Settings(WebAddress.parse("0"), null), comms, engine, clock);
                browser = openPage(view);
            }
            if (flood > 0) {
                flooder = ReadingFlood.start(n, flood, comms.links().get(0).localPort());
            }
            Cpu idle = Cpu.measure(sim, comms, () -> Thread.sleep(IDLE_WINDOW.toMillis()));

            engine.bind("fleetSize", n);
            var run = engine.run(script, "bench/fleet.dolphin");
            check(waitFor(Duration.ofSeconds(300), () -> comms.nodes().stream().allMatch(
                    v -> v.isArmed() && v.getModeName().equals("AUTO") && v.state().relativeAlt() > 5)),
                    "every vehicle flying its mission");
            long browserBefore = browserCpu(browser);
            Cpu guarded = Cpu.measure(sim, comms, () -> Thread.sleep(GUARDED_WINDOW.toMillis()));
            double browserCores = browser == null ? Double.NaN : (browserCpu(browser) - browserBefore) / 1e9 / guarded.seconds();
            boolean early = !reactions.crossed.isEmpty();
            ScriptResult result = run.await();
            long heapFlying = usedHeap(memory) - heapBefore;
            List<Double> ms = reactions.latenciesMs();
            if (result.outcome() != ScriptResult.Outcome.COMPLETED || ms.size() != n || early) {
                System.err.println("fleet " + n + ": " + result + ", " + ms.size() + " reactions of " + n
                        + (early ? ", a cut came during the measuring window" : ""));
                failures++;
            }
            report(n, links, web, flood, heapVehicles, heapFlying, idle, guarded, browserCores, ms);
        } finally {
            if (flooder != null) {
                flooder.close();
            }
            if (browser != null) {
                browser.destroy();
                browser.waitFor();
            }
            if (view != null) {
                view.close();
            }
            sim.destroy();
            sim.waitFor();
            comms.close();
        }
        return failures;
    }

    /** Debian's chromium, headless, on the page; returns once the page streams. */
    private static Process openPage(WebView view) throws Exception {
        Path profile = Files.createTempDirectory("fleet-bench-chromium");
        Process browser = new ProcessBuilder("chromium", "--headless=new", "--no-sandbox", "--disable-gpu",
                "--user-data-dir=" + profile, "--window-size=1440,900", view.address())
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        check(waitFor(Duration.ofSeconds(60), () -> view.viewers() > 0), "the page to open the stream");
        return browser;
    }

    /** CPU of the browser and every process it started (renderer, GPU...), in nanoseconds. */
    private static long browserCpu(Process browser) {
        if (browser == null) {
            return 0;
        }
        return Stream.concat(Stream.of(browser.toHandle()), browser.toHandle().descendants())
                .mapToLong(h -> h.info().totalCpuDuration().map(Duration::toNanos).orElse(0L)).sum();
    }

    /** The with-web run against the run without it, for one size. */
    void compare(int n) {
        Map<String, Object> plain = results.get(results.size() - 2);
        Map<String, Object> web = results.get(results.size() - 1);
        double cpu = (double) web.get("runtimeCoresFlying") / (double) plain.get("runtimeCoresFlying");
        double idle = (double) web.get("runtimeCoresStreaming") / (double) plain.get("runtimeCoresStreaming");
        double p99 = (double) web.get("reactionP99Ms") / (double) plain.get("reactionP99Ms");
        line(String.format(Locale.ROOT, "%5d vehicles, web view with a page open against none: runtime CPU x%.2f flying with guards, "
                + "x%.2f streaming only; reaction p99 %.2f ms against %.2f ms (x%.2f)", n, cpu, idle,
                (double) web.get("reactionP99Ms"), (double) plain.get("reactionP99Ms"), p99));
        Map<String, Object> r = new LinkedHashMap<>();
        r.put("vehicles", n);
        r.put("webCpuRatioFlying", cpu);
        r.put("webCpuRatioStreaming", idle);
        r.put("webReactionP99Ratio", p99);
        results.add(r);
    }

    /** The flooded run against the run without the flood, for one size. */
    void compareFlood(int n, int rate) {
        Map<String, Object> plain = results.get(results.size() - 2);
        Map<String, Object> flooded = results.get(results.size() - 1);
        double p99 = (double) flooded.get("reactionP99Ms") / (double) plain.get("reactionP99Ms");
        double cpu = (double) flooded.get("runtimeCoresFlying") / (double) plain.get("runtimeCoresFlying");
        line(String.format(Locale.ROOT, "%5d vehicles, %d readings/s per vehicle against none: reaction p99 %.2f ms against %.2f ms (x%.2f); "
                + "runtime CPU x%.2f flying with guards", n, rate, (double) flooded.get("reactionP99Ms"),
                (double) plain.get("reactionP99Ms"), p99, cpu));
        Map<String, Object> r = new LinkedHashMap<>();
        r.put("vehicles", n);
        r.put("floodReactionP99Ratio", p99);
        r.put("floodCpuRatioFlying", cpu);
        results.add(r);
    }

    /** CPU of this process (the runtime) and of the simulator process over a window. */
    record Cpu(double seconds, double runtimeCores, double simCores, double framesInPerSecond, Map<String, Double> threadCores,
               double gcCores, double jitCores) {

        interface Window {
            void run() throws Exception;
        }

        static Cpu measure(Process sim, MAVLinkCommunications comms, Window window) throws Exception {
            var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
            long wall = System.nanoTime();
            long cpu = os.getProcessCpuTime();
            long simCpu = simCpu(sim);
            long frames = comms.framesIn();
            Map<Long, Long> threads = threadCpu();
            long gc = gcMillis();
            long jit = ManagementFactory.getCompilationMXBean().getTotalCompilationTime();
            window.run();
            double seconds = (System.nanoTime() - wall) / 1e9;
            Map<String, Double> byThread = new TreeMap<>();
            var mx = ManagementFactory.getThreadMXBean();
            threadCpu().forEach((id, t) -> {
                var info = mx.getThreadInfo(id);
                String name = info == null ? "ended" : info.getThreadName().replaceAll("mavlink-link-\\d+.*", "mavlink-link readers");
                byThread.merge(name, (t - threads.getOrDefault(id, 0L)) / 1e9 / seconds, Double::sum);
            });
            byThread.values().removeIf(c -> c < 0.005);
            return new Cpu(seconds, (os.getProcessCpuTime() - cpu) / 1e9 / seconds, (simCpu(sim) - simCpu) / 1e9 / seconds,
                    (comms.framesIn() - frames) / seconds, byThread, (gcMillis() - gc) / 1e3 / seconds,
                    (ManagementFactory.getCompilationMXBean().getTotalCompilationTime() - jit) / 1e3 / seconds);
        }

        /** Time the collectors took (their threads are not Java threads, so not in threadCores). */
        private static long gcMillis() {
            return ManagementFactory.getGarbageCollectorMXBeans().stream().mapToLong(b -> Math.max(0, b.getCollectionTime())).sum();
        }

        private static Map<Long, Long> threadCpu() {
            var mx = ManagementFactory.getThreadMXBean();
            Map<Long, Long> cpu = new HashMap<>();
            for (long id : mx.getAllThreadIds()) {
                cpu.put(id, mx.getThreadCpuTime(id));
            }
            return cpu;
        }

        private static long simCpu(Process sim) {
            return sim.toHandle().info().totalCpuDuration().map(Duration::toNanos).orElse(0L);
        }
    }

    private void report(int n, int links, boolean web, int flood, long heapVehicles, long heapFlying, Cpu idle, Cpu flying, double browserCores,
                        List<Double> ms) {
        double p50 = percentile(ms, 50);
        double p99 = percentile(ms, 99);
        double max = ms.isEmpty() ? Double.NaN : ms.get(ms.size() - 1);
        line(String.format(Locale.ROOT, "%5d vehicles, %d link(s)%s: %,.0f frames/s in while flying with guards", n, links,
                (web ? ", web view with a page open" : "") + (flood > 0 ? ", " + flood + " readings/s per vehicle" : ""),
                flying.framesInPerSecond()));
        line(String.format(Locale.ROOT, "      runtime CPU: %.3f cores streaming only, %.3f cores flying with guards (%.3f ms/s per vehicle); "
                        + "simulator (reference, same traffic): %.3f and %.3f cores; runtime/simulator %.2f",
                idle.runtimeCores(), flying.runtimeCores(), flying.runtimeCores() * 1000 / n, idle.simCores(), flying.simCores(),
                flying.runtimeCores() / flying.simCores()));
        line(String.format(Locale.ROOT, "      runtime threads flying with guards (cores): %s; garbage collection %.3f, JIT compilation %.3f",
                flying.threadCores().entrySet().stream()
                .map(e -> String.format(Locale.ROOT, "%s %.3f", e.getKey(), e.getValue())).collect(Collectors.joining(", ")),
                flying.gcCores(), flying.jitCores()));
        if (web) {
            line(String.format(Locale.ROOT, "      browser (chromium and its processes, headless) flying with guards: %.3f cores", browserCores));
        }
        line(String.format(Locale.ROOT, "      heap: %.1f KiB per vehicle connected, %.1f KiB per vehicle after the flights",
                heapVehicles / 1024.0 / n, heapFlying / 1024.0 / n));
        line(String.format(Locale.ROOT, "      reaction (SYS_STATUS < %d %% -> DO_SET_MODE RTL), %d cuts: p50 %.2f ms, p99 %.2f ms, max %.2f ms",
                THRESHOLD_PERCENT, ms.size(), p50, p99, max));
        Map<String, Object> r = new LinkedHashMap<>();
        r.put("vehicles", n);
        r.put("links", links);
        r.put("web", web);
        r.put("floodReadingsPerSecondPerVehicle", flood);
        r.put("framesInPerSecond", flying.framesInPerSecond());
        r.put("runtimeCoresStreaming", idle.runtimeCores());
        r.put("runtimeCoresFlying", flying.runtimeCores());
        r.put("simCoresStreaming", idle.simCores());
        r.put("simCoresFlying", flying.simCores());
        r.put("runtimeThreadCoresFlying", flying.threadCores());
        r.put("gcCoresFlying", flying.gcCores());
        if (web) {
            r.put("browserCoresFlying", browserCores);
        }
        r.put("jitCoresFlying", flying.jitCores());
        r.put("heapBytesPerVehicle", heapVehicles / (double) n);
        r.put("heapBytesPerVehicleAfterFlights", heapFlying / (double) n);
        r.put("reactionMs", ms);
        r.put("reactionP50Ms", p50);
        r.put("reactionP99Ms", p99);
        results.add(r);
    }

    static double percentile(List<Double> sorted, int p) {
        if (sorted.isEmpty()) {
            return Double.NaN;
        }
        int i = (int) Math.ceil(p / 100.0 * sorted.size()) - 1;
        return sorted.get(Math.max(0, Math.min(sorted.size() - 1, i)));
    }

    private static long usedHeap(MemoryMXBean memory) throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(100);
        }
        return memory.getHeapMemoryUsage().getUsed();
    }

    private static boolean waitFor(Duration limit, BooleanSupplier condition) throws InterruptedException {
        long end = System.nanoTime() + limit.toNanos();
        while (System.nanoTime() < end) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(50);
        }
        return condition.getAsBoolean();
    }

    private static void check(boolean ok, String what) {
        if (!ok) {
            throw new IllegalStateException("timed out waiting for " + what);
        }
    }

    private void line(String text) {
        System.out.println(text);
        summary.append(text).append('\n');
    }

    private void write() throws Exception {
        Files.writeString(out.resolve("fleet-summary.txt"), summary.toString());
        Files.writeString(out.resolve("fleet.json"), UploadBench.toJson(results));
    }
}
