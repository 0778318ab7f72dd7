package dolphin.mission.model;

import java.util.ArrayList;
import java.util.List;

/**
 * A mission's items as a text table, one row per item: seq, command name, frame name, p1..p4,
 * latitude and longitude (degrees, 7 decimals: exactly the item's degE7) and altitude (metres, as
 * the item carries it: AMSL in GLOBAL_INT). Parameters are the shortest decimals of their floats,
 * {@code nan} for NaN. An item without a position (a non-global frame, x, y and z all 0) shows
 * {@code -} for latitude, longitude and altitude.
 */
public final class MissionTable {

    private static final String[] HEADER = {"seq", "command", "frame", "p1", "p2", "p3", "p4", "lat", "lon", "alt"};
    /** Which columns are left-aligned (names); the rest are numbers, right-aligned. */
    private static final boolean[] LEFT = {false, true, true, false, false, false, false, false, false, false};

    private MissionTable() {
    }

    /** The table, its header line first, each line ending in a newline. */
    public static String format(List<MissionItem> items) {
        List<String[]> rows = new ArrayList<>();
        rows.add(HEADER);
        for (MissionItem it : items) {
            boolean positionless = !ItemText.isGlobal(it.frame()) && it.x() == 0 && it.y() == 0 && it.z() == 0;
            rows.add(new String[] {
                Integer.toString(it.seq()), it.commandName(), it.frameName(),
                ItemText.number(it.param1()), ItemText.number(it.param2()),
                ItemText.number(it.param3()), ItemText.number(it.param4()),
                positionless ? "-" : ItemText.degrees(it.x()),
                positionless ? "-" : ItemText.degrees(it.y()),
                positionless ? "-" : ItemText.number(it.z())});
        }
        int[] width = new int[HEADER.length];
        for (String[] row : rows) {
            for (int c = 0; c < row.length; c++) {
                width[c] = Math.max(width[c], row[c].length());
            }
        }
        StringBuilder sb = new StringBuilder();
        for (String[] row : rows) {
            StringBuilder line = new StringBuilder();
            for (int c = 0; c < row.length; c++) {
                if (c > 0) {
                    line.append("  ");
                }
                String pad = " ".repeat(width[c] - row[c].length());
                line.append(LEFT[c] ? row[c] + pad : pad + row[c]);
            }
            sb.append(line.toString().stripTrailing()).append('\n');
        }
        return sb.toString();
    }
}
