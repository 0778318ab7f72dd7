package dolphin.bench;

import com.MAVLink.enums.MAV_PROTOCOL_CAPABILITY;
import dolphin.core.SystemClock;
import dolphin.mavlink.LinkTimeouts;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkConfig;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mission.file.MissionFile;
import dolphin.mission.file.WaypointsFile;
import dolphin.mission.flight.MissionService;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.transfer.MissionTransferConfig;
import dolphin.mission.transfer.TransferPath;
import dolphin.mission.transfer.TransferResult;
import dolphin.mission.transfer.TransferStatus;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Collectors;

/**
 * Our side of harness/sitl_lossy_uploads.py: one ground station (MAVLinkCommunications on a link,
 * real time, as `dolphin run` has it) that uploads .waypoints files (a mission, a fence, rally points)
 * to ArduCopter SITL, system id 1, when told to on stdin, and answers with one JSON line on stdout.
 * The driver checks the vehicle's lists itself, by a download on a lossless port.
 *
 * <pre>SitlUploads LINK WAYPOINTS_FILE...</pre>
 *
 * Prints "ready" once the vehicle is heard, then reads lines
 * "upload ITEMS|FTP|AUTO DEADLINE_S [mission|fence|rally]" (a mission without the last word),
 * "capabilities WAIT_S" (waits up to WAIT_S for the vehicle's AUTOPILOT_VERSION, asked for at
 * discovery, and answers "capabilities ftp=true|false|unknown": the driver gives discovery's exchange
 * time to end before it points the link elsewhere), "quit" to stop. It answers each upload with
 * {@code result {"path", "kind", "done", "time_s", "error", "resends", "ignored_acks", "verified", "note", "progress",
 * "ftp_offered"}}: done is what the transfer reported, time_s from the call to that report, ftp_offered
 * what the vehicle's AUTOPILOT_VERSION said when the upload began (null: none had arrived, so AUTO
 * takes the items). Before each upload it
 * waits for a heartbeat newer than the command (the driver points the relay at another ground
 * station between uploads), not counted in the time.
 */
public final class SitlUploads {

    /** The words of the upload command for each list. */
    private static final Map<String, MissionType> TYPES =
            Map.of("mission", MissionType.MISSION, "fence", MissionType.FENCE, "rally", MissionType.RALLY);

    private SitlUploads() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 2) {
            System.err.println("usage: SitlUploads LINK WAYPOINTS_FILE...");
            System.exit(2);
        }
        Map<MissionType, List<MissionItem>> lists = new EnumMap<>(MissionType.class);
        for (int i = 1; i < args.length; i++) {
            MissionFile file = WaypointsFile.readFile(Path.of(args[i]));
            if (file.hasMission()) {
                lists.put(MissionType.MISSION, file.mission());
            }
            if (!file.fence().isEmpty()) {
                lists.put(MissionType.FENCE, file.fence().items());
            }
            if (!file.rally().isEmpty()) {
                lists.put(MissionType.RALLY, file.rally().items());
            }
        }
        try (MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of(args[0]), SystemClock.REAL)) {
            comms.start();
            UploadBench.waitFor(() -> comms.node("1") != null, 60, "vehicle 1");
            System.out.println("ready " + lists.entrySet().stream().map(e -> e.getValue().size() + " " + e.getKey().label())
                    .collect(Collectors.joining(", ")));
            System.out.flush();
            BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
            for (String line = in.readLine(); line != null && !line.trim().equals("quit"); line = in.readLine()) {
                String[] words = line.trim().split("\\s+");
                if (words.length == 2 && words[0].equals("capabilities")) {
                    MAVLinkNode node = comms.node("1");
                    long end = System.nanoTime() + (long) (Double.parseDouble(words[1]) * 1e9);
                    while (ftpOffered(node) == null && System.nanoTime() < end) {
                        Thread.sleep(10);
                    }
                    Boolean ftp = ftpOffered(node);
                    System.out.println("capabilities ftp=" + (ftp == null ? "unknown" : ftp));
                    System.out.flush();
                    continue;
                }
                MissionType type = words.length == 4 ? TYPES.get(words[3].toLowerCase(Locale.ROOT)) : MissionType.MISSION;
                if (words.length < 3 || words.length > 4 || !words[0].equals("upload") || !lists.containsKey(type)) {
                    System.out.println("error: " + line + " (no such list among the files, or not 'upload PATH DEADLINE_S [KIND]')");
                    System.out.flush();
                    continue;
                }
                System.out.println("result " + upload(comms, type, lists.get(type), TransferPath.valueOf(words[1]),
                        Integer.parseInt(words[2])));
                System.out.flush();
            }
        }
        System.exit(0);
    }

    /** What AUTO chooses from: the FTP bit of the vehicle's AUTOPILOT_VERSION, null until it arrives. */
    static Boolean ftpOffered(MAVLinkNode node) {
        return node.capabilities().isPresent()
                ? (node.capabilities().getAsLong() & MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_FTP) != 0 : null;
    }

    /** The transfer settings of each path: the defaults, the path forced. */
    static MissionTransferConfig config(TransferPath path) {
        return new MissionTransferConfig(LinkTimeouts.DEFAULT, path);
    }

    static String upload(MAVLinkCommunications comms, MissionType type, List<MissionItem> items, TransferPath path,
            int deadlineSeconds) throws Exception {
        MAVLinkNode node = comms.node("1");
        long asked = comms.clock().nanoTime();
        UploadBench.waitFor(() -> node.state().heartbeatNanos() > asked, 30, "a heartbeat of vehicle 1");
        Boolean ftpOffered = ftpOffered(node);
        AtomicReference<TransferStatus> last = new AtomicReference<>();
        long t0 = System.nanoTime();
        TransferResult r;
        try {
            r = MissionService.of(comms).vehicle(node).transfers().upload()
                    .upload(type, items, config(path), last::set).get(deadlineSeconds, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            r = new TransferResult(false, "not done in " + deadlineSeconds + " s", List.of(), -1, -1);
        }
        double seconds = (System.nanoTime() - t0) / 1e9;
        TransferStatus status = last.get();
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("path", path.name());
        json.put("kind", type.name().toLowerCase(Locale.ROOT));
        json.put("done", r.success());
        json.put("time_s", Math.round(seconds * 1000) / 1000.0);
        json.put("error", r.error());
        json.put("resends", r.resends());
        json.put("ignored_acks", r.ignoredAcks());
        json.put("verified", r.verified());
        json.put("note", r.note());
        json.put("progress", status == null ? null : status.text());
        json.put("ftp_offered", ftpOffered);
        return UploadBench.toJson(json);
    }
}
