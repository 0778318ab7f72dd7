package dolphin.mavlink.mission;

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
 * {@code INDEX CURRENT FRAME COMMAND P1 P2 P3 P4 LAT LON ALT AUTOCONTINUE}. Line 0 is the home.
 *
 * <p>Latitude and longitude are degrees with 7 decimals, exactly the item's degE7; parameters and
 * altitude are the shortest decimals that read back to the same float; NaN is {@code nan} (what
 * Python writes and reads). Frames are the float frames (see {@link FileValues}). The home line
 * has CURRENT 1, like Mission Planner's; the other lines 0. There are no comment lines: QGroundControl
 * and MAVSDK reject lines without exactly 12 fields.
 */
public final class WaypointsFile {

    public static final String HEADER = "QGC WPL 110";
    public static final String EXTENSION = ".waypoints";

    private WaypointsFile() {
    }

    /** The file's text for the items of a mission, item 0 the home (as {@link Mission#items} gives them). */
    public static String write(List<MissionItem> items) {
        FileValues.requireHome(items);
        StringBuilder sb = new StringBuilder(HEADER).append('\n');
        for (int i = 0; i < items.size(); i++) {
            MissionItem it = items.get(i);
            sb.append(String.join("\t",
                    Integer.toString(i),
                    i == 0 ? "1" : "0",
                    Integer.toString(FileValues.fileFrame(it.frame())),
                    Integer.toString(it.command()),
                    FileValues.number(it.param1()),
                    FileValues.number(it.param2()),
                    FileValues.number(it.param3()),
                    FileValues.number(it.param4()),
                    FileValues.degrees(it.x()),
                    FileValues.degrees(it.y()),
                    FileValues.number(it.z()),
                    it.autocontinue() ? "1" : "0")).append('\n');
        }
        return sb.toString();
    }

    public static void write(Path file, List<MissionItem> items) throws IOException {
        Files.writeString(file, write(items), StandardCharsets.UTF_8);
    }

    /**
     * The items of a QGC WPL 110 text, numbered 0, 1, ... in file order (like mavwp; the INDEX
     * column is not trusted). Blank lines and {@code #} comment lines (mavwp writes them) are
     * skipped. Like mavwp, a line-0 command 0 (Mission Planner's home) becomes NAV_WAYPOINT.
     *
     * @throws IllegalArgumentException naming the line, for a text that is not such a file
     */
    public static List<MissionItem> read(String text) {
        String[] lines = MissionFileText.withoutBom(text).split("\r?\n|\r", -1);
        int n = 0;
        while (n < lines.length && lines[n].isBlank()) {
            n++;
        }
        if (n == lines.length || !lines[n].strip().equals(HEADER)) {
            throw new IllegalArgumentException("not a " + HEADER + " file: the first line must be '" + HEADER + "'"
                    + (n < lines.length ? ", found '" + abbreviate(lines[n].strip()) + "'" : ", the file is empty"));
        }
        List<MissionItem> items = new ArrayList<>();
        for (int i = n + 1; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] f = line.split("\\s+");
            if (f.length != 12) {
                throw new IllegalArgumentException("line " + (i + 1) + ": expected 12 tab-separated fields"
                        + " (INDEX CURRENT FRAME COMMAND P1 P2 P3 P4 LAT LON ALT AUTOCONTINUE), found " + f.length);
            }
            try {
                int seq = items.size();
                int command = FileValues.parseInt(f[3]);
                if (seq == 0 && command == 0) {
                    command = MAV_CMD.MAV_CMD_NAV_WAYPOINT;
                }
                items.add(new MissionItem(seq, command, FileValues.itemFrame(FileValues.parseInt(f[2])),
                        FileValues.parseFloat(f[4]), FileValues.parseFloat(f[5]), FileValues.parseFloat(f[6]),
                        FileValues.parseFloat(f[7]), FileValues.degE7(f[8]), FileValues.degE7(f[9]),
                        FileValues.parseFloat(f[10]), FileValues.parseInt(f[11]) != 0));
            } catch (NumberFormatException | ArithmeticException e) {
                throw new IllegalArgumentException("line " + (i + 1) + ": " + e.getMessage(), e);
            }
        }
        if (items.isEmpty()) {
            throw new IllegalArgumentException("the file has no items, not even the home (line 0)");
        }
        return items;
    }

    /** The items of a file, UTF-8 with or without a byte-order mark; errors name the file. */
    public static List<MissionItem> read(Path file) throws IOException {
        return MissionFileText.parse(file, WaypointsFile::read);
    }

    private static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 40) + "...";
    }
}
