package dolphin.bench;

import dolphin.core.SystemClock;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkConfig;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mission.flight.MissionService;
import dolphin.mission.model.MissionItem;
import dolphin.mission.transfer.MissionTransferConfig;
import dolphin.mission.transfer.TransferPath;
import dolphin.mission.transfer.TransferProgress;
import dolphin.mission.transfer.TransferResult;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * The uploader of whatever dolphin jar is on the classpath, in a JVM of its own, serving
 * {@link LossyUploadBench} the line protocol of bench/mavproxy_wpload.py: run once with this
 * working tree's jar and once with a baseline jar (an earlier build), both against lossless
 * simulated vehicles of the bench's process, it compares the two builds like for like. Without
 * {@code --path} it uses only what the earlier builds have too (the default
 * {@link MissionTransferConfig}); with it, {@link LossyUploadBench#config} of that path.
 *
 * <pre>UploadServer [--path ITEMS|FTP|AUTO] --port-file FILE</pre>
 *
 * Listens on udpin:127.0.0.1 (an ephemeral port, written to FILE), waits for vehicle 1 and its
 * home, prints "ready", then per line: {@code upload ITEMS.json DEADLINE} uploads and prints
 * {"outcome": "done" | "failed" | "not done", "ms", "resends", "detail"}; {@code ack} prints
 * {} (the time above already runs to the vehicle's MISSION_ACK); {@code quit} prints the jar and exits.
 */
public final class UploadServer {

    private UploadServer() {
    }

    public static void main(String[] args) throws Exception {
        List<String> arguments = List.of(args);
        Path portFile = Path.of(arguments.get(arguments.indexOf("--port-file") + 1));
        MissionTransferConfig config = arguments.contains("--path") ? config(arguments.get(arguments.indexOf("--path") + 1))
                : MissionTransferConfig.DEFAULT;
        try (MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of("udpin:127.0.0.1:0"), SystemClock.REAL)) {
            comms.start();
            Path tmp = Path.of(portFile + ".tmp");
            Files.writeString(tmp, comms.links().get(0).localPort() + "\n");
            Files.move(tmp, portFile, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
            MAVLinkNode node = UploadBench.awaitNode(comms, "1");
            System.out.println("ready");
            BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
            for (String line; (line = in.readLine()) != null && !line.equals("quit"); ) {
                String[] words = line.trim().split("\\s+");
                System.out.println(words[0].equals("ack") ? "{}" : upload(node, config, readItems(Path.of(words[1])),
                        Double.parseDouble(words[2])));
            }
        }
        System.out.println("{\"jar\": " + UploadBench.toJson(String.valueOf(
                MissionTransferConfig.class.getProtectionDomain().getCodeSource().getLocation())) + "}");
        System.exit(0);
    }

    /** Apart, so that an earlier build without {@link TransferPath} never links it. */
    private static MissionTransferConfig config(String path) {
        return LossyUploadBench.config(TransferPath.valueOf(path));
    }

    private static String upload(MAVLinkNode node, MissionTransferConfig config, List<MissionItem> items, double deadline) throws Exception {
        long t0 = System.nanoTime();
        try {
            TransferResult r = MissionService.of(node.communications()).vehicle(node).transfers().upload()
                    .upload(items, config, TransferProgress.NONE).get((long) (deadline * 1000), TimeUnit.MILLISECONDS);
            return String.format(Locale.ROOT, "{\"outcome\": \"%s\", \"ms\": %.3f, \"resends\": %d, \"detail\": %s}",
                    r.success() ? "done" : "failed", (System.nanoTime() - t0) / 1e6, r.resends(),
                    UploadBench.toJson(r.success() ? "" : r.error()));
        } catch (TimeoutException e) {
            return String.format(Locale.ROOT, "{\"outcome\": \"not done\", \"ms\": null, \"resends\": 0, \"detail\": \"not done in %.0f s\"}",
                    deadline);
        }
    }

    /** The items UploadBench.itemsJson wrote: one row a line, [seq, command, frame, param1..4, x, y, z, autocontinue]. */
    static List<MissionItem> readItems(Path file) throws Exception {
        List<MissionItem> items = new ArrayList<>();
        for (String line : Files.readAllLines(file)) {
            String row = line.trim();
            if (!row.startsWith("[") || row.equals("[")) {
                continue;
            }
            String[] v = row.replaceAll("[\\[\\],]+$", "").replace("[", "").replace("\"", "").split(",\\s*");
            items.add(new MissionItem(Integer.parseInt(v[0]), Integer.parseInt(v[1]), Integer.parseInt(v[2]), number(v[3]), number(v[4]),
                    number(v[5]), number(v[6]), Integer.parseInt(v[7]), Integer.parseInt(v[8]), number(v[9]), v[10].equals("1")));
        }
        return items;
    }

    private static float number(String s) {
        return s.equals("nan") ? Float.NaN : Float.parseFloat(s);
    }
}
