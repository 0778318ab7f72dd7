package dolphin.mission.file;

import dolphin.mission.model.ItemText;
import dolphin.mission.model.BadItemException;
import dolphin.mission.model.Fence;
import dolphin.mission.model.Mission;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.RallyPoints;
import com.MAVLink.enums.MAV_CMD;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * QGC WPL 110 ({@code .waypoints}), the text format of Mission Planner, MAVProxy and pymavlink's
 * mavwp: the line {@code QGC WPL 110}, then one line per item with 12 tab-separated fields
 * {@code INDEX CURRENT FRAME COMMAND P1 P2 P3 P4 LAT LON ALT AUTOCONTINUE}. In a mission, line 0 is
 * the home.
 *
 * <p>Latitude and longitude are degrees with 7 decimals, exactly the item's degE7; parameters and
 * altitude are the shortest decimals that read back to the same float; NaN is {@code nan} (what
 * Python writes and reads). Frames are the float frames (see {@link FileValues}). The home line
 * has CURRENT 1, like Mission Planner's; the other lines 0. There are no comment lines: QGroundControl
 * and MAVSDK reject lines without exactly 12 fields.
 *
 * <p>A file holds one kind of items (docs/mission-files.md): a mission; a fence, every line a fence
 * command (5000 to 5004) and no home, as MAVProxy's {@code fence save} and ArduPilot's autotest write
 * them; or rally points, every line a NAV_RALLY_POINT. Reading also takes {@code QGC WPL 120}, the
 * older QGroundControl files without a home line, and MAVProxy's legacy fence and rally files
 * ({@link MavproxyAirspaceFile}).
 */
public final class WaypointsFile {

    public static final String HEADER = "QGC WPL 110";
    /** QGroundControl's older text missions: no home line. */
    public static final String HEADER_120 = "QGC WPL 120";
    public static final String EXTENSION = ".waypoints";

    private WaypointsFile() {
    }

    /** The file's text for the items of a mission, item 0 the home (as {@link Mission#items} gives them). */
    public static String write(List<MissionItem> items) {
        FileValues.requireHome(items);
        return lines(items, true);
    }

    /** The file's text for a fence's or rally points' items: no home, every line CURRENT 0. */
    public static String writeItems(List<MissionItem> items) {
        if (items.isEmpty()) {
            throw new IllegalArgumentException("a fence or rally file needs at least one item");
        }
        return lines(items, false);
    }

    private static String lines(List<MissionItem> items, boolean home) {
        StringBuilder sb = new StringBuilder(HEADER).append('\n');
        for (int i = 0; i < items.size(); i++) {
            MissionItem it = items.get(i);
            sb.append(String.join("\t",
                    Integer.toString(i),
                    home && i == 0 ? "1" : "0",
                    Integer.toString(ItemText.fileFrame(it.frame())),
                    Integer.toString(it.command()),
                    ItemText.number(it.param1()),
                    ItemText.number(it.param2()),
                    ItemText.number(it.param3()),
                    ItemText.number(it.param4()),
                    ItemText.degrees(it.x()),
                    ItemText.degrees(it.y()),
                    ItemText.number(it.z()),
                    it.autocontinue() ? "1" : "0")).append('\n');
        }
        return sb.toString();
    }

    public static void write(Path file, List<MissionItem> items) throws IOException {
        Files.writeString(file, write(items), StandardCharsets.UTF_8);
    }

    /**
     * The items of a QGC WPL 110 mission, numbered 0, 1, ... in file order (like mavwp; the INDEX
     * column is not trusted). Blank lines and {@code #} comment lines (mavwp writes them) are
     * skipped. Like mavwp, a line-0 command 0 (Mission Planner's home) becomes NAV_WAYPOINT.
     *
     * @throws IllegalArgumentException naming the line, for a text that is not such a file, or a
     *         file of a fence or rally points
     */
    public static List<MissionItem> read(String text) {
        MissionFile file = readFile(text);
        if (!file.hasMission()) {
            throw new IllegalArgumentException("the file holds " + (file.fence().isEmpty() ? "rally points" : "a fence")
                    + ", not a mission");
        }
        return file.mission();
    }

    /**
     * A mission, a fence or rally points, whichever the file holds.
     *
     * @throws IllegalArgumentException naming the line and what was expected
     */
    public static MissionFile readFile(String text) {
        String[] lines = MissionFileText.withoutBom(text).split("\r?\n|\r", -1);
        int n = 0;
        while (n < lines.length && (lines[n].isBlank() || lines[n].strip().startsWith("#"))) {
            n++;
        }
        String first = n < lines.length ? lines[n].strip() : "";
        if (MavproxyAirspaceFile.isFence(first)) {
            return MissionFile.of(List.of()).withFence(MavproxyAirspaceFile.readFence(lines));
        }
        if (MavproxyAirspaceFile.isRally(first)) {
            return MissionFile.of(List.of()).withRally(MavproxyAirspaceFile.readRally(lines));
        }
        boolean v120 = first.equals(HEADER_120);
        if (!v120 && !first.equals(HEADER)) {
            throw new IllegalArgumentException("not a " + HEADER + " file: the first line must be '" + HEADER + "'"
                    + (n < lines.length ? ", found '" + abbreviate(first) + "'" : ", the file is empty"));
        }
        List<MissionItem> items = new ArrayList<>();
        List<Integer> lineNumbers = new ArrayList<>();
        if (v120) {
            // No home line: item 0 is a placeholder the vehicle replaces with its home.
            items.add(new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MissionItem.GLOBAL_INT, 0, 0, 0, 0, 0, 0, 0, true));
            lineNumbers.add(n + 1);
        }
        for (int i = n + 1; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            items.add(item(line, items.size(), i + 1, v120));
            lineNumbers.add(i + 1);
        }
        if (items.isEmpty()) {
            throw new IllegalArgumentException("the file has no items, not even the home (line 0)");
        }
        return classify(items, lineNumbers, v120);
    }

    private static MissionItem item(String line, int seq, int lineNumber, boolean v120) {
        String[] f = line.split("\\s+");
        if (f.length != 12) {
            throw new IllegalArgumentException("line " + lineNumber + ": expected 12 tab-separated fields"
                    + " (INDEX CURRENT FRAME COMMAND P1 P2 P3 P4 LAT LON ALT AUTOCONTINUE), found " + f.length);
        }
        try {
            int command = FileValues.parseInt(f[3]);
            if (seq == 0 && command == 0) {
                command = MAV_CMD.MAV_CMD_NAV_WAYPOINT;
            }
            float p1 = FileValues.parseFloat(f[4]);
            if (v120 && command == MAV_CMD.MAV_CMD_DO_JUMP) {
                p1 += 1; // its targets counted without the home line
            }
            return new MissionItem(seq, command, ItemText.itemFrame(FileValues.parseInt(f[2])), p1,
                    FileValues.parseFloat(f[5]), FileValues.parseFloat(f[6]), FileValues.parseFloat(f[7]),
                    FileValues.degE7(f[8], 90), FileValues.degE7(f[9], 180), FileValues.parseFloat(f[10]),
                    FileValues.parseInt(f[11]) != 0);
        } catch (NumberFormatException | ArithmeticException e) {
            throw new IllegalArgumentException("line " + lineNumber + ": " + e.getMessage(), e);
        }
    }

    /** A fence when every item is a fence command, rally points when every item is one; else a mission without either. */
    private static MissionFile classify(List<MissionItem> items, List<Integer> lineNumbers, boolean v120) {
        try {
            if (!v120 && items.stream().allMatch(it -> Fence.isFenceCommand(it.command()))) {
                return MissionFile.of(List.of()).withFence(Fence.of(items));
            }
            if (!v120 && items.stream().allMatch(it -> it.command() == MAV_CMD.MAV_CMD_NAV_RALLY_POINT)) {
                return MissionFile.of(List.of()).withRally(RallyPoints.of(items));
            }
        } catch (BadItemException e) {
            throw new IllegalArgumentException("line " + lineNumbers.get(e.index()) + ": " + e.getMessage(), e);
        }
        for (int i = 0; i < items.size(); i++) {
            MissionItem it = items.get(i);
            if (Fence.isFenceCommand(it.command()) || it.command() == MAV_CMD.MAV_CMD_NAV_RALLY_POINT) {
                throw new IllegalArgumentException("line " + lineNumbers.get(i) + ": " + it.commandName() + " in a"
                        + " mission: a " + HEADER + " file holds a mission, a fence or rally points, each in a file"
                        + " of its own");
            }
        }
        return MissionFile.of(items);
    }

    /** The items of a file, UTF-8 with or without a byte-order mark; errors name the file. */
    public static List<MissionItem> read(Path file) throws IOException {
        return MissionFileText.parse(file, WaypointsFile::read);
    }

    /** Whatever a file holds, UTF-8 with or without a byte-order mark; errors name the file. */
    public static MissionFile readFile(Path file) throws IOException {
        return MissionFileText.parse(file, WaypointsFile::readFile);
    }

    private static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 40) + "...";
    }
}
