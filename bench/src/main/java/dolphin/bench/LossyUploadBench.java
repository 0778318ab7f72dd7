package dolphin.bench;

import dolphin.core.SystemClock;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkConfig;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mission.flight.MissionService;
import dolphin.mission.model.MissionItem;
import dolphin.mission.transfer.MissionTransferConfig;
import dolphin.mission.transfer.MissionVerification;
import dolphin.mission.transfer.TransferPath;
import dolphin.mission.transfer.TransferProgress;
import dolphin.mission.transfer.TransferResult;
import dolphin.sim.FaultModel;
import dolphin.sim.SimFleet;
import dolphin.sim.SimVehicle;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Collectors;

/**
 * Mission uploads over lossy links (bench/README.md, "Lossy-link upload benchmark"): at 0, 5, 10,
 * 20 and 30 % loss both ways ({@link FaultModel#loss}, seeded), 10, 100 and 500 items, each cell
 * compares in the same run our upload over the item protocol, ours over MAVLink FTP, and the
 * reference, bench/mavproxy_wpload.py (pymavlink doing what MAVProxy's {@code wp load} does, in its
 * own process against its own simulated vehicle with the same loss and seed). Every upload is
 * verified afterwards against the list the simulated vehicle stores. Real UDP on 127.0.0.1, real time.
 *
 * <pre>LossyUploadBench OUT_DIR PYTHON REFERENCE_SCRIPT [--quick] [--lossless] [--baseline-jar JAR]
 *                  [--rounds N] [--cell-seconds S] [--deadline S]</pre>
 *
 * The lossless cells alternate the uploaders round by round (and the protocol floor of
 * {@link UploadBench#floorMs}); with {@code --baseline-jar}, also {@link UploadServer} in two JVMs,
 * one on this tree's jar and one on the baseline's, for "lossless no slower than before", in turn
 * first and second round by round; {@code --lossless} runs only those rounds. The lossy
 * cells run side by side, each on its own vehicle, at most N rounds and no new round after S
 * seconds; a reference upload not done after the deadline is stopped. Writes OUT_DIR/lossy.json
 * (every upload) and OUT_DIR/lossy-summary.txt.
 */
public final class LossyUploadBench {

    static final double[] LOSSES = {0, 0.05, 0.10, 0.20, 0.30};
    static final int[] SIZES = UploadBench.SIZES;
    static final int WARMUP_SIZE = 100;
    /** ArduPilot (and the simulator) cancels an upload 8 s after its last item: by then the stored list is final. */
    static final double SETTLE_SECONDS = 10;
    /** "Lossless no slower than before": the rounds' ratios within this factor, the spread of two alternating runs on a shared machine. */
    static final double NO_SLOWER = 1.10;
    static final double TARGET_RATIO = 0.25;
    /**
     * Lossless rounds with a baseline: on a shared machine the median of 41 paired ratios of
     * millisecond uploads ranged from 0.63 to 1.33 between runs of the same two builds; 401 pin it
     * to a few per cent, and take about a minute.
     */
    static final int BEFORE_AFTER_ROUNDS = 401;

    enum Way {
        ITEMS("ours, item protocol"), FTP("ours, FTP"), REFERENCE("reference (wp load)"),
        CURRENT("this build, items, own JVM"), BASELINE("baseline build, own JVM");

        final String label;

        Way(String label) {
            this.label = label;
        }

        boolean ours() {
            return this == ITEMS || this == FTP;
        }
    }

    /** How one upload went, as its uploader saw it. */
    record Attempt(String outcome, double ms, int resends, String detail) {
        boolean done() {
            return outcome.equals("done");
        }
    }

    /** One upload: the attempt, whether the vehicle then held exactly that list, and the reference's MISSION_ACK. */
    record Sample(Attempt attempt, boolean onVehicle, String ack, double ackMs) {
        boolean verified() {
            return attempt.done() && onVehicle;
        }
    }

    private final Path out;
    private final String python;
    private final String reference;
    private final Options options;
    private final StringBuilder summary = new StringBuilder();
    private final Map<String, Cell> cells = new LinkedHashMap<>();
    private final Map<Integer, double[]> floor = new LinkedHashMap<>();
    private final List<AutoCloseable> resources = new ArrayList<>();
    private String referenceVersions = "?";

    /**
     * @param deadline when a reference upload is stopped as not done
     * @param oursCap the same for ours: only a guard against a hung run (ours give up by themselves after their silence budget)
     */
    record Options(boolean quick, String baselineJar, int rounds, double cellSeconds, double deadline, double oursCap, int reps, int warmup,
                   List<Integer> lossySizes) {
        static Options parse(List<String> args) {
            boolean quick = args.contains("--quick");
            String baseline = value(args, "--baseline-jar", null);
            return new Options(quick, baseline, Integer.parseInt(value(args, "--rounds", quick ? "2" : "10")),
                    Double.parseDouble(value(args, "--cell-seconds", quick ? "30" : "420")),
                    Double.parseDouble(value(args, "--deadline", quick ? "20" : "120")), quick ? 60 : 600,
                    quick ? 3 : baseline != null ? BEFORE_AFTER_ROUNDS : 41, quick ? 2 : 10,
                    args.contains("--lossless") ? List.of() : quick ? List.of(10, 100) : Arrays.stream(SIZES).boxed().toList());
        }

        private static String value(List<String> args, String name, String otherwise) {
            int i = args.indexOf(name);
            return i < 0 ? otherwise : args.get(i + 1);
        }
    }

    LossyUploadBench(Path out, String python, String reference, Options options) {
        this.out = out;
        this.python = python;
        this.reference = reference;
        this.options = options;
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 3) {
            System.err.println("usage: LossyUploadBench OUT_DIR PYTHON REFERENCE_SCRIPT [--quick] [--lossless] [--baseline-jar JAR] "
                    + "[--rounds N] [--cell-seconds S] [--deadline S]");
            System.exit(2);
        }
        Path out = Path.of(args[0]);
        Files.createDirectories(out.resolve("lossy"));
        Options options = Options.parse(Arrays.asList(args).subList(3, args.length));
        System.exit(new LossyUploadBench(out, args[1], args[2], options).run() ? 0 : 1);
    }

    /** The one place this benchmark's transfer configs are made: the defaults, with the path forced. */
    static MissionTransferConfig config(TransferPath path) {
        return new MissionTransferConfig(MissionTransferConfig.DEFAULT.timeouts(), path);
    }

    /** The same seed for every uploader of a cell, a different one per cell. */
    static long seed(double loss, int size) {
        return Math.round(loss * 100) * 1000 + size;
    }

    static String key(Way way, double loss, int size) {
        return way + "/" + Math.round(loss * 100) + "/" + size;
    }

    boolean run() throws Exception {
        String date = java.time.LocalDate.now().toString();
        line("lossy-link upload benchmark, %s, %s, %d cores, Java %s; loopback UDP, simulated copters, real time", date, cpu(),
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"));
        line("rounds per cell: lossless %d (after %d warm-up), lossy at most %d and none started after %.0f s; deadline of an upload:"
                + " the reference %.0f s, ours %.0f s", options.reps, options.warmup, options.rounds, options.cellSeconds, options.deadline, options.oursCap);
        try (MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of("udpin:127.0.0.1:0"), SystemClock.REAL)) {
            comms.start();
            int port = comms.links().get(0).localPort();
            try {
                lossless(comms, port);
                lossy(comms, port);
            } finally {
                for (AutoCloseable r : resources) {
                    r.close();
                }
            }
        }
        boolean ok = report(date);
        Files.writeString(out.resolve("lossy-summary.txt"), summary);
        return ok;
    }

    // ---- lossless: the uploaders alternate round by round -----------------------------------------

    private void lossless(MAVLinkCommunications comms, int port) throws Exception {
        SimFleet fleet = own(UploadBench.fleet(port, 1, FaultModel.NONE));
        MAVLinkNode node = UploadBench.awaitNode(comms, "1");
        Map<Way, VehicleUploader> ways = new LinkedHashMap<>();
        ways.put(Way.ITEMS, new InProcess(fleet, 1, node, config(TransferPath.ITEMS)));
        ways.put(Way.FTP, new InProcess(fleet, 1, node, config(TransferPath.FTP)));
        if (options.baselineJar != null) {
            String bench = Path.of(LossyUploadBench.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
            String jar = Path.of(MissionTransferConfig.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
            ways.put(Way.CURRENT, startServer(Way.CURRENT, bench, jar, "--path", TransferPath.ITEMS.name()));
            ways.put(Way.BASELINE, startServer(Way.BASELINE, bench, options.baselineJar));
        }
        ways.put(Way.REFERENCE, own(OutOfProcess.start(List.of(python, reference), out.resolve("lossy/reference-0.port"), FaultModel.NONE,
                out.resolve("lossy/reference-0.json"))));
        for (int i = 0; i < options.warmup; i++) {     // the JIT of every side: not measured
            UploadBench.floorMs(comms, node, WARMUP_SIZE + 2);
            for (VehicleUploader u : ways.values()) {
                u.upload(WARMUP_SIZE, options.deadline);
            }
        }
        for (int n : SIZES) {
            double[] f = new double[options.reps];
            for (int r = 0; r < options.reps; r++) {
                f[r] = UploadBench.floorMs(comms, node, n + 2);
                for (Way w : order(ways.keySet(), r)) {
                    cell(w, 0, n).samples.add(ways.get(w).upload(n, options.deadline));
                }
            }
            floor.put(n, f);
        }
        for (Way w : List.of(Way.REFERENCE, Way.CURRENT, Way.BASELINE)) {
            if (ways.get(w) instanceof OutOfProcess p) {
                String versions = p.quit();
                if (w == Way.REFERENCE) {
                    referenceVersions = versions;
                }
            }
        }
    }

    /** The uploaders of round {@code r}: the two builds swap places every other round, so neither always follows the other. */
    private static List<Way> order(Collection<Way> ways, int r) {
        List<Way> order = new ArrayList<>(ways);
        int current = order.indexOf(Way.CURRENT);
        if (r % 2 == 1 && current >= 0) {
            Collections.swap(order, current, order.indexOf(Way.BASELINE));
        }
        return order;
    }

    private OutOfProcess startServer(Way way, String benchClasses, String jar, String... arguments) throws Exception {
        String lib = Path.of(jar).resolveSibling("lib").resolve("*").toString();
        String name = way.name().toLowerCase(Locale.ROOT);
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Dorg.slf4j.simpleLogger.defaultLogLevel=warn", "-cp", benchClasses + ":" + jar + ":" + lib, UploadServer.class.getName()));
        command.addAll(List.of(arguments));
        return own(OutOfProcess.start(command, out.resolve("lossy/" + name + ".port"), FaultModel.NONE, out.resolve("lossy/" + name + ".json")));
    }

    // ---- lossy: every cell on its own vehicle, side by side ----------------------------------------

    private void lossy(MAVLinkCommunications comms, int port) throws Exception {
        List<Thread> threads = new ArrayList<>();
        int sysid = 2;
        for (double loss : LOSSES) {
            if (loss == 0) {
                continue;
            }
            for (int n : options.lossySizes) {
                FaultModel faults = FaultModel.loss(loss, seed(loss, n));
                for (Way w : List.of(Way.ITEMS, Way.FTP)) {
                    SimFleet fleet = own(UploadBench.fleet(port, sysid, faults));
                    cell(w, loss, n).uploader = new InProcess(fleet, sysid, null, config(w == Way.ITEMS ? TransferPath.ITEMS : TransferPath.FTP));
                    sysid++;
                }
                String name = "reference-" + Math.round(loss * 100) + "-" + n;
                cell(Way.REFERENCE, loss, n).uploader = own(OutOfProcess.start(List.of(python, reference),
                        out.resolve("lossy/" + name + ".port"), faults, out.resolve("lossy/" + name + ".json")));
            }
        }
        for (Cell c : cells.values()) {
            if (c.uploader instanceof InProcess p) {
                p.node = UploadBench.awaitNode(comms, String.valueOf(p.sysid));
            }
        }
        for (Cell c : cells.values()) {
            if (c.loss > 0) {
                Thread t = new Thread(c, "cell " + key(c.way, c.loss, c.size));
                t.start();
                threads.add(t);
            }
        }
        for (Thread t : threads) {
            t.join();
        }
    }

    private Cell cell(Way way, double loss, int size) {
        return cells.computeIfAbsent(key(way, loss, size), k -> new Cell(way, loss, size));
    }

    private <T extends AutoCloseable> T own(T resource) {
        resources.add(resource);
        return resource;
    }

    /** The rounds of one (uploader, loss, size). */
    final class Cell implements Runnable {
        final Way way;
        final double loss;
        final int size;
        final List<Sample> samples = new ArrayList<>();
        VehicleUploader uploader;
        String error;

        Cell(Way way, double loss, int size) {
            this.way = way;
            this.loss = loss;
            this.size = size;
        }

        @Override
        public void run() {
            long start = System.nanoTime();
            try {
                for (int r = 0; r < options.rounds && (r == 0 || (System.nanoTime() - start) / 1e9 < options.cellSeconds); r++) {
                    samples.add(uploader.upload(size, way.ours() ? options.oursCap : options.deadline));
                }
            } catch (Exception e) {
                error = e.toString();
            }
        }
    }

    // ---- the uploaders ---------------------------------------------------------------------------

    /** Uploads to one simulated vehicle, then checks what the vehicle stores. */
    abstract static class VehicleUploader implements AutoCloseable {
        /** Uploads so far per vehicle, whichever uploader made them. */
        private static final Map<SimVehicle, AtomicInteger> UPLOADS = new ConcurrentHashMap<>();
        final SimFleet fleet;
        final int sysid;

        VehicleUploader(SimFleet fleet, int sysid) {
            this.fleet = fleet;
            this.sysid = sysid;
        }

        abstract Attempt attempt(List<MissionItem> items, double deadline) throws Exception;

        /** The MISSION_ACK the uploader heard, and when; none by default. */
        String[] ack() throws IOException {
            return new String[] {null, null};
        }

        /**
         * One upload of {@code size} items, a different list from the one before (the altitudes
         * shift by a metre an upload), so a stale list on the vehicle cannot pass; once the vehicle
         * has finished with it (ACK sent, or its own timeout), its stored list must be exactly that.
         */
        final Sample upload(int size, double deadline) throws Exception {
            SimVehicle vehicle = fleet.vehicle(sysid);
            int shift = 1 + UPLOADS.computeIfAbsent(vehicle, v -> new AtomicInteger()).getAndIncrement() % 50;
            List<MissionItem> items = UploadBench.mission(vehicle.home(), size).stream()
                    .map(i -> i.seq() == 0 ? i : new MissionItem(i.seq(), i.command(), i.frame(), i.param1(), i.param2(), i.param3(),
                            i.param4(), i.x(), i.y(), i.z() + shift, i.autocontinue()))
                    .toList();
            Attempt a = attempt(items, deadline);
            long end = System.nanoTime() + (long) (SETTLE_SECONDS * 1e9);
            while (vehicle.missionUploading() && System.nanoTime() < end) {
                Thread.sleep(5);
            }
            boolean same = MissionVerification.firstDifference(items, vehicle.mission()).isEmpty();
            String[] ack = ack();
            return new Sample(a, same, ack[0], ack[1] == null ? Double.NaN : Double.parseDouble(ack[1]));
        }

        @Override
        public void close() throws Exception {
        }
    }

    /** Ours, in this process, through the communications every in-process vehicle shares. */
    static final class InProcess extends VehicleUploader {
        final MissionTransferConfig config;
        volatile MAVLinkNode node;

        InProcess(SimFleet fleet, int sysid, MAVLinkNode node, MissionTransferConfig config) {
            super(fleet, sysid);
            this.node = node;
            this.config = config;
        }

        @Override
        Attempt attempt(List<MissionItem> items, double deadline) throws Exception {
            long t0 = System.nanoTime();
            try {
                TransferResult r = MissionService.of(node.communications()).vehicle(node).transfers().upload()
                        .upload(items, config, TransferProgress.NONE).get((long) (deadline * 1000), TimeUnit.MILLISECONDS);
                return new Attempt(r.success() ? "done" : "failed", (System.nanoTime() - t0) / 1e6, r.resends(),
                        r.success() ? r.note() : r.error());
            } catch (TimeoutException e) {
                return new Attempt("not done", Double.NaN, 0, String.format(Locale.ROOT, "not done in %.0f s", deadline));
            }
        }
    }

    /**
     * An uploader in a process of its own speaking bench/mavproxy_wpload.py's line protocol (that
     * script, or {@link UploadServer}), against its own simulated vehicle (system id 1, the given
     * loss both ways) in this process.
     */
    static final class OutOfProcess extends VehicleUploader {
        private final Process process;
        private final BufferedReader in;
        private final Writer commands;
        private final Path items;

        private OutOfProcess(SimFleet fleet, Process process, Path items) {
            super(fleet, 1);
            this.process = process;
            this.in = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
            this.commands = new OutputStreamWriter(process.getOutputStream(), StandardCharsets.UTF_8);
            this.items = items;
        }

        /** Starts {@code command} with the port file as its last argument, its vehicle, and waits for "ready". */
        static OutOfProcess start(List<String> command, Path portFile, FaultModel faults, Path items) throws Exception {
            Files.deleteIfExists(portFile);
            List<String> cmd = new ArrayList<>(command);
            cmd.add("--port-file");
            cmd.add(portFile.toString());
            Process p = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT).start();
            UploadBench.waitFor(() -> Files.exists(portFile) || !p.isAlive(), 60, portFile.toString());
            if (!p.isAlive()) {
                throw new IllegalStateException(cmd + " ended with " + p.exitValue());
            }
            SimFleet fleet = UploadBench.fleet(Integer.parseInt(Files.readString(portFile).trim()), 1, faults);
            OutOfProcess u = new OutOfProcess(fleet, p, items);
            String ready = u.in.readLine();
            if (!"ready".equals(ready)) {
                u.close();
                throw new IllegalStateException(cmd + ": " + ready);
            }
            return u;
        }

        private String ask(String line) throws IOException {
            commands.write(line + "\n");
            commands.flush();
            String answer = in.readLine();
            if (answer == null) {
                throw new IOException("the uploader process ended");
            }
            return answer;
        }

        @Override
        Attempt attempt(List<MissionItem> list, double deadline) throws Exception {
            Files.writeString(items, UploadBench.itemsJson(list));
            String r = ask(String.format(Locale.ROOT, "upload %s %.1f", items, deadline));
            return new Attempt(UploadBench.jsonString(r, "outcome"), number(r, "ms"), (int) number(r, "resends"),
                    UploadBench.jsonString(r, "detail"));
        }

        @Override
        String[] ack() throws IOException {
            String r = ask("ack");
            double type = number(r, "ack");
            return new String[] {Double.isNaN(type) ? null : String.valueOf((int) type),
                    Double.isNaN(number(r, "ack_ms")) ? null : String.valueOf(number(r, "ack_ms"))};
        }

        /** The last line: versions. */
        String quit() throws Exception {
            String last = ask("quit");
            process.waitFor(10, TimeUnit.SECONDS);
            return last;
        }

        @Override
        public void close() throws Exception {
            if (process.isAlive()) {
                process.destroy();
            }
            fleet.close();
        }
    }

    /** A number in a one-line JSON object; NaN if null or absent. */
    static double number(String json, String key) {
        int i = json.indexOf("\"" + key + "\": ");
        if (i < 0) {
            return Double.NaN;
        }
        int start = i + key.length() + 4;
        int end = start;
        while (end < json.length() && ",}".indexOf(json.charAt(end)) < 0) {
            end++;
        }
        String v = json.substring(start, end).trim();
        return v.equals("null") ? Double.NaN : Double.parseDouble(v);
    }

    // ---- the report ------------------------------------------------------------------------------

    private boolean report(String date) throws IOException {
        line("reference: %s", referenceVersions);
        line("");
        line("per cell: uploads verified / total (the vehicle holds exactly the list and the uploader reported it done);"
                + " times in ms of the uploads reported done, median / p90; resends, median");
        line("%-5s %-5s  %-24s %-16s %-19s %8s  %s", "loss", "items", "uploader", "verified", "median / p90", "resends", "notes");
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("date", date);
        json.put("cpu", cpu());
        json.put("reference", referenceVersions);
        json.put("options", options.toString());
        List<Object> all = new ArrayList<>();
        for (double loss : LOSSES) {
            for (int n : SIZES) {
                for (Way w : Way.values()) {
                    Cell c = cells.get(key(w, loss, n));
                    if (c == null) {
                        continue;
                    }
                    double[] t = times(c);
                    line("%4.0f%% %5d  %-24s %4d / %-9d %8s / %8s %8.0f  %s", loss * 100, n, w.label, verified(c), c.samples.size(),
                            ms(UploadBench.median(t)), ms(UploadBench.p90(t)), UploadBench.median(resends(c)), notes(c));
                    all.add(cellJson(c));
                }
            }
        }
        json.put("cells", all);
        Map<String, Object> floors = new LinkedHashMap<>();
        floor.forEach((n, f) -> floors.put(String.valueOf(n), UploadBench.list(f)));
        json.put("floor_ms", floors);
        Files.writeString(out.resolve("lossy.json"), UploadBench.toJson(json) + "\n");

        line("");
        line("ours against the reference, same run (median time of ours / median time of the reference's uploads reported done)");
        line("%-5s %-5s  %12s %12s  %s", "loss", "items", "items/ref", "FTP/ref", "reference median");
        for (double loss : LOSSES) {
            for (int n : measured(loss)) {
                double ref = median(Way.REFERENCE, loss, n);
                line("%4.0f%% %5d  %12s %12s  %s", loss * 100, n, ratio(Way.ITEMS, loss, n), ratio(Way.FTP, loss, n),
                        Double.isNaN(ref) ? String.format(Locale.ROOT, "none done in %.0f s", options.deadline) : ms(ref) + " ms");
            }
        }
        Files.writeString(out.resolve("lossy-table.md"), markdown());
        line("lossless, against the floor (N + 2 command round trips on the same link, UploadBench.floorMs):");
        for (int n : SIZES) {
            double f = UploadBench.median(floor.get(n));
            line("  %3d items: floor %s ms; item protocol %.2f x, FTP %.2f x, reference %.2f x", n, ms(f),
                    median(Way.ITEMS, 0, n) / f, median(Way.FTP, 0, n) / f, median(Way.REFERENCE, 0, n) / f);
        }

        line("");
        boolean ok = true;
        for (Way w : List.of(Way.ITEMS, Way.FTP)) {
            List<String> short_ = cells.values().stream().filter(c -> c.way == w && (c.samples.isEmpty() || verified(c) < c.samples.size()))
                    .map(c -> String.format(Locale.ROOT, "%.0f%%/%d: %d of %d", c.loss * 100, c.size, verified(c), c.samples.size()))
                    .toList();
            int total = cells.values().stream().filter(c -> c.way == w).mapToInt(c -> c.samples.size()).sum();
            int verified = cells.values().stream().filter(c -> c.way == w).mapToInt(this::verified).sum();
            ok &= short_.isEmpty();
            line("target %-58s %s (%d / %d%s)", w.label + ": 100 % verified at every level", short_.isEmpty() ? "met" : "MISSED", verified, total,
                    short_.isEmpty() ? "" : "; short: " + String.join(", ", short_));
        }
        for (Way w : List.of(Way.ITEMS, Way.FTP)) {
            for (double loss : new double[] {0.05, 0.10}) {
                for (int n : measured(loss)) {
                    line("target %-58s %s", String.format(Locale.ROOT, "%s, %.0f%% loss, %d items: <= %.2f x the reference", w.label,
                            loss * 100, n, TARGET_RATIO), ratioTarget(w, loss, n));
                }
            }
        }
        if (options.baselineJar == null) {
            line("target %-58s not checked (no --baseline-jar)", "lossless no slower than before");
        } else {
            for (int n : SIZES) {
                double r = pairedRatio(cells.get(key(Way.CURRENT, 0, n)), cells.get(key(Way.BASELINE, 0, n)));
                line("target %-58s %s (%.2f x; medians %s against %s ms)", "lossless, " + n + " items, no slower than the baseline build",
                        r <= NO_SLOWER ? "met" : "MISSED", r, ms(median(Way.CURRENT, 0, n)), ms(median(Way.BASELINE, 0, n)));
            }
            line("  (each build in a JVM of its own, UploadServer, alternating; the median of the rounds' ratios, which saw the same load,"
                    + " within %.2f x; baseline %s)", NO_SLOWER, options.baselineJar);
        }
        for (Cell c : cells.values()) {
            if (c.error != null) {
                line("cell %s stopped: %s", key(c.way, c.loss, c.size), c.error);
                ok = false;
            }
        }
        return ok;
    }

    /** The per-cell table as bench/README.md shows it: verified / total, median (max), ratios to the reference's median. */
    private String markdown() {
        StringBuilder b = new StringBuilder("| loss | items | ours, item protocol | ours, FTP | reference (wp load) | items / ref | FTP / ref |\n"
                + "|---:|---:|---:|---:|---:|---:|---:|\n");
        for (double loss : LOSSES) {
            for (int n : measured(loss)) {
                b.append(String.format(Locale.ROOT, "| %.0f %% | %d | %s | %s | %s | %s | %s |%n", loss * 100, n, cellText(Way.ITEMS, loss, n),
                        cellText(Way.FTP, loss, n), cellText(Way.REFERENCE, loss, n), ratio(Way.ITEMS, loss, n), ratio(Way.FTP, loss, n)));
            }
        }
        return b.toString();
    }

    private String cellText(Way w, double loss, int n) {
        Cell c = cells.get(key(w, loss, n));
        double[] t = times(c);
        String time = t.length == 0 ? String.format(Locale.ROOT, "none done in %.0f s", options.deadline)
                : duration(UploadBench.median(t)) + " (" + duration(Arrays.stream(t).max().orElseThrow()) + ")";
        return verified(c) + "/" + c.samples.size() + ", " + time;
    }

    private static String duration(double ms) {
        return ms < 1000 ? ms(ms) + " ms" : String.format(Locale.ROOT, "%.1f s", ms / 1000);
    }

    /** The median over the rounds of a's time / b's time in the same round. */
    private static double pairedRatio(Cell a, Cell b) {
        double[] r = new double[Math.min(a.samples.size(), b.samples.size())];
        for (int i = 0; i < r.length; i++) {
            r[i] = a.samples.get(i).attempt.ms / b.samples.get(i).attempt.ms;
        }
        return UploadBench.median(r);
    }

    /** The sizes measured at this loss. */
    private int[] measured(double loss) {
        return Arrays.stream(SIZES).filter(n -> cells.containsKey(key(Way.REFERENCE, loss, n))).toArray();
    }

    private String ratioTarget(Way w, double loss, int n) {
        Cell ref = cells.get(key(Way.REFERENCE, loss, n));
        double ours = median(w, loss, n);
        double theirs = UploadBench.median(times(ref));
        if (Double.isNaN(ours)) {
            return "MISSED (none of ours done)";
        }
        if (Double.isNaN(theirs)) {   // the reference finished none within its deadline: it takes longer than that
            double bound = ours / (options.deadline * 1000);
            return String.format(Locale.ROOT, "%s (< %.3f x: the reference did none of %d within %.0f s)", bound <= TARGET_RATIO ? "met" : "MISSED",
                    bound, ref.samples.size(), options.deadline);
        }
        double r = ours / theirs;
        return String.format(Locale.ROOT, "%s (%.3f x: %s against %s ms)", r <= TARGET_RATIO ? "met" : "MISSED", r, ms(ours), ms(theirs));
    }

    private String ratio(Way w, double loss, int n) {
        double ref = median(Way.REFERENCE, loss, n);
        double ours = median(w, loss, n);
        if (Double.isNaN(ref)) {
            return Double.isNaN(ours) ? "-" : String.format(Locale.ROOT, "< %.3f x", ours / (options.deadline * 1000));
        }
        return String.format(Locale.ROOT, "%.3f x", ours / ref);
    }

    private double median(Way w, double loss, int n) {
        Cell c = cells.get(key(w, loss, n));
        return c == null ? Double.NaN : UploadBench.median(times(c));
    }

    private int verified(Cell c) {
        return (int) c.samples.stream().filter(Sample::verified).count();
    }

    private static double[] times(Cell c) {
        return c == null ? new double[0] : c.samples.stream().filter(s -> s.attempt.done()).mapToDouble(s -> s.attempt.ms).toArray();
    }

    private static double[] resends(Cell c) {
        return c.samples.stream().mapToDouble(s -> s.attempt.resends).toArray();
    }

    /** What else happened: uploads not done (by outcome), done but not on the vehicle, the reference's ACKs. */
    private String notes(Cell c) {
        List<String> notes = new ArrayList<>();
        Map<String, Long> outcomes = c.samples.stream().filter(s -> !s.attempt.done())
                .collect(Collectors.groupingBy(s -> s.attempt.outcome, LinkedHashMap::new, Collectors.counting()));
        outcomes.forEach((o, k) -> notes.add(k + " " + o));
        long wrong = c.samples.stream().filter(s -> s.attempt.done() && !s.onVehicle).count();
        if (wrong > 0) {
            notes.add(wrong + " done but not on the vehicle");
        }
        long falseFailures = c.samples.stream().filter(s -> !s.attempt.done() && s.onVehicle).count();
        if (falseFailures > 0) {
            notes.add(falseFailures + " reported failed though on the vehicle");
        }
        if (c.way == Way.REFERENCE) {
            long done = c.samples.stream().filter(s -> s.attempt.done()).count();
            long accepted = c.samples.stream().filter(s -> s.attempt.done() && "0".equals(s.ack)).count();
            double[] ackMs = c.samples.stream().filter(s -> s.attempt.done() && "0".equals(s.ack)).mapToDouble(s -> s.ackMs).toArray();
            notes.add(String.format(Locale.ROOT, "ACCEPTED heard after %d of %d done (median %s ms)", accepted, done, ms(UploadBench.median(ackMs))));
        }
        c.samples.stream().filter(s -> !s.verified()).map(s -> s.attempt.detail).filter(d -> d != null && !d.isEmpty()).findFirst()
                .ifPresent(d -> notes.add("e.g. " + d));
        if (c.error != null) {
            notes.add("stopped: " + c.error);
        }
        return String.join("; ", notes);
    }

    private Map<String, Object> cellJson(Cell c) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("uploader", c.way.name().toLowerCase(Locale.ROOT));
        m.put("loss", c.loss);
        m.put("items", c.size);
        List<Object> samples = new ArrayList<>();
        for (Sample s : c.samples) {
            Map<String, Object> j = new LinkedHashMap<>();
            j.put("outcome", s.attempt.outcome);
            j.put("ms", Double.isNaN(s.attempt.ms) ? null : Math.round(s.attempt.ms * 1000) / 1000.0);
            j.put("resends", s.attempt.resends);
            j.put("on_vehicle", s.onVehicle);
            j.put("verified", s.verified());
            if (c.way == Way.REFERENCE) {
                j.put("ack", s.ack);
                j.put("ack_ms", Double.isNaN(s.ackMs) ? null : s.ackMs);
            }
            j.put("detail", s.attempt.detail == null ? "" : s.attempt.detail);
            samples.add(j);
        }
        m.put("samples", samples);
        if (c.error != null) {
            m.put("error", c.error);
        }
        return m;
    }

    private static String ms(double v) {
        if (Double.isNaN(v)) {
            return "-";
        }
        return v < 100 ? String.format(Locale.ROOT, "%.1f", v) : String.format(Locale.ROOT, "%,.0f", v);
    }

    static String cpu() {
        try {
            return Files.readAllLines(Path.of("/proc/cpuinfo")).stream().filter(l -> l.startsWith("model name"))
                    .map(l -> l.substring(l.indexOf(':') + 1).trim()).findFirst().orElse("?");
        } catch (IOException e) {
            return "?";
        }
    }

    private void line(String format, Object... args) {
        String s = String.format(Locale.ROOT, format, args);
        System.out.println(s);
        summary.append(s).append('\n');
    }
}
