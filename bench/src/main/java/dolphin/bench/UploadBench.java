package dolphin.bench;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_RESULT;
import dolphin.core.Position;
import dolphin.core.SystemClock;
import dolphin.mavlink.CommandResult;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkConfig;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mission.flight.MissionService;
import dolphin.mission.model.MissionItem;
import dolphin.mission.transfer.MissionTransferConfig;
import dolphin.mission.transfer.TransferPath;
import dolphin.mission.transfer.MissionVerification;
import dolphin.mission.transfer.TransferProgress;
import dolphin.mission.transfer.TransferResult;
import dolphin.sim.FaultModel;
import dolphin.sim.SimFleet;
import dolphin.sim.VehicleKind;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

/**
 * End-to-end mission upload times over loopback UDP against a simulated copter (dolphin.sim) on a
 * real-time clock, compared in the same run with the protocol floor (N + 2 COMMAND_LONG /
 * COMMAND_ACK round trips on the same link) and with a pymavlink uploader (bench/pymavlink_upload.py)
 * against the same kind of simulated vehicle. Lossy links: {@link LossyUploadBench}.
 * Not JMH: these are wall-clock times of whole transfers, in ms. See bench/README.md.
 *
 * <pre>UploadBench OUT_DIR PYTHON PYMAVLINK_SCRIPT [--quick]</pre>
 *
 * Writes OUT_DIR/upload.json (every sample) and prints a summary (also OUT_DIR/upload-summary.txt).
 */
public final class UploadBench {

    static final int[] SIZES = {10, 100, 500};
    /** The floor command: MAV_CMD_REQUEST_MESSAGE for HEARTBEAT, which the simulator does not send on request: one COMMAND_ACK (FAILED) back, no other message. */
    static final int FLOOR_COMMAND = MAV_CMD.MAV_CMD_REQUEST_MESSAGE;

    private final Path out;
    private final String python;
    private final String script;
    private final boolean quick;
    private final StringBuilder summary = new StringBuilder();
    private final Map<String, Object> json = new LinkedHashMap<>();

    UploadBench(Path out, String python, String script, boolean quick) {
        this.out = out;
        this.python = python;
        this.script = script;
        this.quick = quick;
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 3) {
            System.err.println("usage: UploadBench OUT_DIR PYTHON PYMAVLINK_SCRIPT [--quick]");
            System.exit(2);
        }
        Path out = Path.of(args[0]);
        Files.createDirectories(out);
        boolean quick = args.length > 3 && args[3].equals("--quick");
        int failures = new UploadBench(out, args[1], args[2], quick).run();
        System.exit(failures == 0 ? 0 : 1);
    }

    /** Home, then NAV_WAYPOINTs on a zig-zag north of it, 20-70 m above home: a valid mission of {@code n} items. */
    static List<MissionItem> mission(Position home, int n) {
        List<MissionItem> items = new ArrayList<>(n);
        items.add(MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, home, 0, 0, 0, 0));
        for (int i = 1; i < n; i++) {
            Position p = Position.fromDegrees(home.latitudeDegrees() + i * 2e-5, home.longitudeDegrees() + (i % 2) * 3e-5,
                    home.hae() + 20 + i % 50);
            items.add(MissionItem.at(i, MAV_CMD.MAV_CMD_NAV_WAYPOINT, p, 0, 2, 0, Float.NaN));
        }
        return items;
    }

    int run() throws Exception {
        int failures = 0;
        String date = java.time.LocalDate.now().toString();
        line("mission upload benchmark, %s, %d cores, Java %s; loopback UDP, simulated copter on a real-time clock",
                date, Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"));
        json.put("date", date);
        int reps = quick ? 3 : 21;

        // ---- (3) pymavlink: its own process, fleet (a lossless copter, sysid 1) and port; it uploads
        // when told to, between our measurements, so both see the same conditions
        Position home = SimFleet.Config.of(1, VehicleKind.COPTER, new InetSocketAddress("127.0.0.1", 1)).home();
        List<String> cmd = new ArrayList<>(List.of(python, script, "--port-file", out.resolve("pymavlink.port").toString(),
                "--warmup", quick ? "2" : "10"));
        for (int n : SIZES) {
            Path f = out.resolve("items-" + n + ".json");
            Files.writeString(f, itemsJson(mission(home, n)));
            cmd.add(f.toString());
        }
        Files.deleteIfExists(out.resolve("pymavlink.port"));
        Process proc = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        BufferedReader pyIn = new BufferedReader(new InputStreamReader(proc.getInputStream(), StandardCharsets.UTF_8));
        java.io.Writer pyOutW = new java.io.OutputStreamWriter(proc.getOutputStream(), StandardCharsets.UTF_8);
        waitFor(() -> Files.exists(out.resolve("pymavlink.port")), 20, "pymavlink_upload.py's port file");
        SimFleet pyFleet = fleet(Integer.parseInt(Files.readString(out.resolve("pymavlink.port")).trim()), 1, FaultModel.NONE);
        Map<Integer, double[]> py = new LinkedHashMap<>();
        String pj = null;

        // ---- (1)+(2) floor and our uploads, lossless --------------------------------------------
        Map<Integer, double[]> floor = new LinkedHashMap<>();
        Map<Integer, double[]> ours = new LinkedHashMap<>();
        Map<Integer, double[]> oursDownload = new LinkedHashMap<>();
        try (MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of("udpin:127.0.0.1:0"), SystemClock.REAL)) {
            comms.start();
            int port = comms.links().get(0).localPort();
            List<SimFleet> fleets = new ArrayList<>();
            try {
                SimFleet lossless = fleet(port, 1, FaultModel.NONE);
                fleets.add(lossless);
                MAVLinkNode node = awaitNode(comms, "1");
                // the item protocol, which the floor's round trips stand for (the default would take FTP where offered)
                MissionTransferConfig config = LossyUploadBench.config(TransferPath.ITEMS);
                String ready = pyIn.readLine();
                if (!"ready".equals(ready)) {
                    throw new IllegalStateException("pymavlink_upload.py: " + ready);
                }

                // warm-up (JIT of both sides): not measured
                for (int i = 0; i < (quick ? 2 : 10); i++) {
                    floorMs(comms, node, 102);
                    uploadMs(node, mission(node.getHome(), 100), config, lossless, 1);
                }
                for (int n : SIZES) {
                    List<MissionItem> items = mission(node.getHome(), n);
                    double[] f = new double[reps];
                    double[] u = new double[reps];
                    double[] d = new double[reps];
                    double[] q = new double[reps];
                    for (int r = 0; r < reps; r++) {          // floor, ours and pymavlink alternate: same conditions
                        f[r] = floorMs(comms, node, n + 2);
                        double[] ud = uploadMs(node, items, config, lossless, 1);
                        if (ud == null) {
                            failures++;
                            u[r] = Double.NaN;
                        } else {
                            u[r] = ud[0];
                            d[r] = ud[1];
                        }
                        pyOutW.write(n + "\n");
                        pyOutW.flush();
                        String answer = pyIn.readLine();
                        if (answer == null || answer.startsWith("fail")) {
                            line("pymavlink upload of %d items: %s", n, answer);
                            failures++;
                            q[r] = Double.NaN;
                        } else {
                            q[r] = Double.parseDouble(answer);
                        }
                    }
                    py.put(n, q);
                    floor.put(n, f);
                    ours.put(n, u);
                    oursDownload.put(n, d);
                }

                pyOutW.write("quit\n");
                pyOutW.flush();
                pj = pyIn.readLine();
                if (!proc.waitFor(10, TimeUnit.SECONDS)) {
                    proc.destroy();
                }
                // the last pymavlink upload was the 500-item mission: the vehicle must hold it
                String diff = MissionVerification.firstDifference(mission(home, SIZES[SIZES.length - 1]),
                        pyFleet.vehicle(1).mission()).orElse(null);
                if (diff != null) {
                    line("pymavlink: the vehicle's mission differs: %s", diff);
                    failures++;
                }
                pyFleet.close();
                Files.writeString(out.resolve("pymavlink-upload.json"), pj == null ? "" : pj + "\n");

                // ---- report ours ------------------------------------------------------------------
                line("");
                line("lossless, %d runs each (after warm-up); ms, median / p90", reps);
                line("%-6s %18s %18s %18s %10s %12s", "items", "floor (N+2 RTT)", "dolphin upload", "(download)", "up/floor", "RTT median");
                Map<String, Object> lossless0 = new LinkedHashMap<>();
                for (int n : SIZES) {
                    double[] f = floor.get(n);
                    double[] u = ours.get(n);
                    line("%-6d %8.1f / %7.1f %8.1f / %7.1f %8.1f / %7.1f %9.2fx %9.3f ms", n, median(f), p90(f), median(u), p90(u),
                            median(oursDownload.get(n)), p90(oursDownload.get(n)), median(u) / median(f), median(f) / (n + 2));
                    lossless0.put(String.valueOf(n), Map.of("floor_ms", list(f), "upload_ms", list(u), "download_ms", list(oursDownload.get(n))));
                }
                json.put("lossless", lossless0);
            } finally {
                fleets.forEach(SimFleet::close);
                pyFleet.close();
                if (proc.isAlive()) {
                    proc.destroy();
                }
            }
        }

        String pyInfo = pj == null ? "?" : jsonString(pj, "pymavlink") + ", Python " + jsonString(pj, "python");
        if (pj == null || !pj.contains("\"errors\": []")) {
            line("pymavlink errors: %s", pj == null ? "no report" : pj.substring(pj.indexOf("\"errors\"")));
            failures++;
        }
        line("");
        line("pymavlink uploader (pymavlink %s, MAVWPLoader + MISSION_ITEM_INT per request, as MAVProxy), %d runs each; ms", pyInfo, reps);
        line("%-6s %18s %18s %12s %12s", "items", "pymavlink upload", "dolphin upload", "dolphin/py", "py/floor");
        Map<String, Object> pyJson = new LinkedHashMap<>();
        for (int n : SIZES) {
            double[] q = py.get(n);
            line("%-6d %8.1f / %7.1f %8.1f / %7.1f %11.2fx %11.2fx", n, median(q), p90(q), median(ours.get(n)), p90(ours.get(n)),
                    median(ours.get(n)) / median(q), median(q) / median(floor.get(n)));
            pyJson.put(String.valueOf(n), list(q));
        }
        json.put("pymavlink", pyJson);

        // ---- targets -----------------------------------------------------------------------------
        line("");
        for (int n : SIZES) {
            double r = median(ours.get(n)) / median(floor.get(n));
            line("target %-52s %s (%.2fx)", "lossless " + n + " items <= 1.3 x floor", r <= 1.3 ? "met" : "MISSED", r);
        }
        for (int n : SIZES) {
            double r = median(ours.get(n)) / median(py.get(n));
            line("target %-52s %s (%.2fx its time)", "lossless " + n + " items faster than pymavlink", r < 1 ? "met" : "MISSED", r);
        }

        Files.writeString(out.resolve("upload-summary.txt"), summary);
        Files.writeString(out.resolve("upload.json"), toJson(json));
        return failures;
    }

    /**
     * Uploads and then downloads to verify; returns {upload ms, download ms}, or null (and the
     * reason printed) if it failed or did not verify.
     */
    double[] uploadMs(MAVLinkNode node, List<MissionItem> items, MissionTransferConfig config, SimFleet fleet, int sysid) throws Exception {
        long t0 = System.nanoTime();
        TransferResult up = MissionService.of(node.communications()).vehicle(node).transfers().upload().upload(items, config, TransferProgress.NONE).get(120, TimeUnit.SECONDS);
        long t1 = System.nanoTime();
        if (!up.success()) {
            line("upload of %d items: %s", items.size(), up.error());
            return null;
        }
        long t2 = System.nanoTime();
        TransferResult down = null;
        for (int attempt = 0; attempt < 3 && (down == null || !down.success()); attempt++) {
            down = MissionService.of(node.communications()).vehicle(node).transfers().download().download(config, TransferProgress.NONE).get(120, TimeUnit.SECONDS);
        }
        long t3 = System.nanoTime();
        if (!down.success()) {
            line("download after the upload of %d items: %s", items.size(), down.error());
            return null;
        }
        String diff = MissionVerification.firstDifference(items, down.items()).orElse(null);
        if (diff == null) {
            diff = MissionVerification.firstDifference(items, fleet.vehicle(sysid).mission()).orElse(null);
        }
        if (diff != null) {
            line("upload of %d items did not verify: %s", items.size(), diff);
            return null;
        }
        return new double[] {(t1 - t0) / 1e6, (t3 - t2) / 1e6};
    }

    /**
     * {@code n} COMMAND_LONG / COMMAND_ACK round trips, one after the other, on the same link; ms.
     * Each command is sent from the completion of the one before, on the communications thread,
     * as the upload's state machine sends each item from the handling of its request.
     */
    static double floorMs(MAVLinkCommunications comms, MAVLinkNode node, int n) throws Exception {
        CompletableFuture<Void> done = new CompletableFuture<>();
        long t0 = System.nanoTime();
        chain(comms, node, n, done);
        done.get(30, TimeUnit.SECONDS);
        return (System.nanoTime() - t0) / 1e6;
    }

    private static void chain(MAVLinkCommunications comms, MAVLinkNode node, int left, CompletableFuture<Void> done) {
        if (left == 0) {
            done.complete(null);
            return;
        }
        comms.command(node, FLOOR_COMMAND, 0).whenComplete((r, e) -> {
            if (e != null) {
                done.completeExceptionally(e);
            } else if (r.result() != MAV_RESULT.MAV_RESULT_FAILED || r.attempts() != 1) {
                done.completeExceptionally(new IllegalStateException("floor round trip: unexpected " + r));
            } else {
                chain(comms, node, left - 1, done);
            }
        });
    }

    static SimFleet fleet(int gcsPort, int sysid, FaultModel faults) throws IOException {
        SimFleet f = new SimFleet(SimFleet.Config.of(1, VehicleKind.COPTER, new InetSocketAddress("127.0.0.1", gcsPort))
                .withFirstSysid(sysid).withFaults(faults), SystemClock.REAL);
        f.start();
        return f;
    }

    static MAVLinkNode awaitNode(MAVLinkCommunications comms, String id) throws InterruptedException {
        waitFor(() -> comms.node(id) != null && comms.node(id).getHome() != null, 30, "vehicle " + id + " and its home");
        return comms.node(id);
    }

    static void waitFor(BooleanSupplier condition, double seconds, String what) throws InterruptedException {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > end) {
                throw new IllegalStateException("timed out after " + seconds + " s waiting for " + what);
            }
            Thread.sleep(10);
        }
    }

    // ---- statistics and output ----------------------------------------------------------------------

    static double median(double[] v) {
        return quantile(v, 0.5);
    }

    /** The 90th percentile, nearest rank. */
    static double p90(double[] v) {
        return quantile(v, 0.9);
    }

    static double quantile(double[] v, double q) {
        double[] s = Arrays.stream(v).filter(x -> !Double.isNaN(x)).sorted().toArray();
        if (s.length == 0) {
            return Double.NaN;
        }
        if (q == 0.5 && s.length % 2 == 0) {
            return (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
        }
        return s[Math.min(s.length - 1, (int) Math.ceil(q * s.length) - 1)];
    }

    static double max(double[] v) {
        return Arrays.stream(v).max().orElse(Double.NaN);
    }

    static List<Double> list(double[] v) {
        return Arrays.stream(v).map(x -> Math.round(x * 1000) / 1000.0).boxed().toList();
    }

    void line(String format, Object... args) {
        String s = String.format(Locale.ROOT, format, args);
        System.out.println(s);
        summary.append(s).append('\n');
    }

    static String itemsJson(List<MissionItem> items) {
        StringBuilder b = new StringBuilder("[\n");
        for (MissionItem i : items) {
            b.append(String.format(Locale.ROOT, "[%d, %d, %d, %s, %s, %s, %s, %d, %d, %s, %d]", i.seq(), i.command(), i.frame(),
                    f(i.param1()), f(i.param2()), f(i.param3()), f(i.param4()), i.x(), i.y(), f(i.z()), i.autocontinue() ? 1 : 0));
            b.append(i.seq() == items.size() - 1 ? "\n" : ",\n");
        }
        return b.append("]\n").toString();
    }

    private static String f(float v) {
        return Float.isNaN(v) ? "\"nan\"" : Float.toString(v);
    }

    static double[] jsonArray(String json, String key) {
        int i = json.indexOf(key);
        if (i < 0) {
            throw new IllegalStateException("no " + key + " in pymavlink_upload.py's output: " + json);
        }
        int start = i + key.length();
        String body = json.substring(start, json.indexOf(']', start));
        return Arrays.stream(body.split(",")).map(String::trim).filter(s -> !s.isEmpty()).mapToDouble(Double::parseDouble).toArray();
    }

    static String jsonString(String json, String key) {
        int i = json.indexOf("\"" + key + "\": \"");
        if (i < 0) {
            return "?";
        }
        int start = i + key.length() + 5;
        return json.substring(start, json.indexOf('"', start));
    }

    static String toJson(Object o) {
        if (o instanceof Map<?, ?> m) {
            StringBuilder b = new StringBuilder("{");
            m.forEach((k, v) -> b.append(b.length() > 1 ? ", " : "").append('"').append(k).append("\": ").append(toJson(v)));
            return b.append('}').toString();
        }
        if (o instanceof List<?> l) {
            StringBuilder b = new StringBuilder("[");
            l.forEach(v -> b.append(b.length() > 1 ? ", " : "").append(toJson(v)));
            return b.append(']').toString();
        }
        if (o instanceof String s) {
            StringBuilder b = new StringBuilder("\"");
            for (char c : s.toCharArray()) {
                if (c == '"' || c == '\\') {
                    b.append('\\').append(c);
                } else if (c < 0x20) {
                    b.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
                } else {
                    b.append(c);
                }
            }
            return b.append('"').toString();
        }
        return String.valueOf(o);
    }
}
