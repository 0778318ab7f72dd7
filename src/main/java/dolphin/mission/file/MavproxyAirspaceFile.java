package dolphin.mission.file;

import dolphin.mission.model.Fence;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.RallyPoints;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * The two text formats MAVProxy's {@code fence load} and {@code rally load} still read, from the days
 * of FENCE_POINT and RALLY_POINT messages (ArduPilot's autotest keeps files of both):
 * <ul>
 * <li>a fence: one {@code lat lon} line a point; the first is the return point, the others a
 * polygon to stay inside, the last repeating the polygon's first vertex to close it;</li>
 * <li>rally points: one {@code RALLY lat lon alt break_alt land_dir flags} line each, heights above
 * home.</li>
 * </ul>
 * Both become today's items (what pymavlink's MissionItemProtocol_Fence and _Rally make of them):
 * a FENCE_RETURN_POINT and POLYGON_VERTEX_INCLUSION items in MAV_FRAME_GLOBAL, and NAV_RALLY_POINTs in
 * GLOBAL_RELATIVE_ALT. A rally line's break altitude, landing direction and flags have no place in
 * a NAV_RALLY_POINT (ArduPilot dropped them with RALLY_POINT) and are not kept. {@code #} lines are
 * comments.
 */
final class MavproxyAirspaceFile {

    private static final Pattern FENCE_LINE = Pattern.compile("[-+]?[0-9.]+\\s+[-+]?[0-9.]+");

    private MavproxyAirspaceFile() {
    }

    /** Whether a file's first line is one of these formats' (and not a QGC WPL header). */
    static boolean isFence(String firstLine) {
        return FENCE_LINE.matcher(firstLine.strip()).matches();
    }

    static boolean isRally(String firstLine) {
        return firstLine.strip().toUpperCase(Locale.ROOT).startsWith("RALLY ");
    }

    /** @param lines the file's lines; errors name them from 1 */
    static Fence readFence(String[] lines) {
        List<int[]> points = new ArrayList<>();
        List<Integer> lineNumbers = new ArrayList<>();
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] f = line.split("\\s+");
            if (f.length != 2) {
                throw new IllegalArgumentException("line " + (i + 1) + ": a fence point line is 'lat lon', found "
                        + f.length + " fields");
            }
            points.add(new int[] {degrees(f[0], 90, i), degrees(f[1], 180, i)});
            lineNumbers.add(i + 1);
        }
        if (points.size() < 5) {
            throw new IllegalArgumentException("a fence file has a return point, at least 3 vertices and the first vertex"
                    + " again to close the polygon: at least 5 points, found " + points.size());
        }
        int[] first = points.get(1);
        int[] last = points.get(points.size() - 1);
        if (first[0] != last[0] || first[1] != last[1]) {
            throw new IllegalArgumentException("line " + lineNumbers.get(points.size() - 1) + ": the last point must repeat"
                    + " the polygon's first vertex (line " + lineNumbers.get(1) + ") to close it");
        }
        List<MissionItem> items = new ArrayList<>();
        int[] ret = points.get(0);
        items.add(new MissionItem(0, MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT, MissionItem.GLOBAL_INT, 0, 0, 0, 0, ret[0],
                ret[1], 0, false));
        int vertices = points.size() - 2;
        for (int i = 1; i <= vertices; i++) {
            int[] v = points.get(i);
            items.add(new MissionItem(i, MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION, MissionItem.GLOBAL_INT,
                    vertices, 0, 0, 0, v[0], v[1], 0, false));
        }
        return Fence.of(items);
    }

    static RallyPoints readRally(String[] lines) {
        List<MissionItem> items = new ArrayList<>();
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] f = line.split("\\s+");
            if (f.length != 7 || !f[0].equalsIgnoreCase("RALLY")) {
                throw new IllegalArgumentException("line " + (i + 1) + ": a rally line is 'RALLY lat lon alt break_alt"
                        + " land_dir flags', found " + (f.length != 7 ? f.length + " fields" : "'" + f[0] + "'"));
            }
            float alt;
            try {
                alt = FileValues.parseFloat(f[3]);
                FileValues.parseFloat(f[4]);
                FileValues.parseFloat(f[5]);
                FileValues.parseInt(f[6]);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("line " + (i + 1) + ": " + e.getMessage(), e);
            }
            items.add(new MissionItem(items.size(), MAV_CMD.MAV_CMD_NAV_RALLY_POINT,
                    MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0, 0, degrees(f[1], 90, i), degrees(f[2], 180, i),
                    alt, false));
        }
        if (items.isEmpty()) {
            throw new IllegalArgumentException("the rally file has no RALLY lines");
        }
        return RallyPoints.of(items);
    }

    private static int degrees(String text, double limit, int line) {
        try {
            return FileValues.degE7(text, limit);
        } catch (NumberFormatException | ArithmeticException e) {
            throw new IllegalArgumentException("line " + (line + 1) + ": " + e.getMessage(), e);
        }
    }
}
