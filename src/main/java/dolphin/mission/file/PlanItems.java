package dolphin.mission.file;

import dolphin.mission.model.ItemText;
import dolphin.mission.model.MissionItem;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The items of a QGroundControl mission in each form its files have had, read the way
 * QGroundControl's MissionItem::load converts them: the first .mission files' {@code "missionItem"}
 * with {@code param1..param4} keys and a {@code coordinate}; then {@code SimpleItem}s with four
 * {@code params} and a {@code coordinate}; now seven {@code params}. ComplexItems (surveys, corridor
 * scans) are flattened into the items QGroundControl expanded into them.
 *
 * <p>Two things QGroundControl resolves when it loads a plan are resolved here too (docs/mission-files.md):
 * a DO_JUMP's param1 is the {@code doJumpId} of its target, turned into the target's item number;
 * an item whose altitude QGroundControl was to "calculate above terrain" and never did (param7 null)
 * flies at its {@code Altitude} in MAV_FRAME_GLOBAL_TERRAIN_ALT, which ArduPilot follows from its own
 * terrain data.
 */
final class PlanItems {

    /** QGroundControl's AltitudeModeCalcAboveTerrain. */
    static final int ALTITUDE_CALC_ABOVE_TERRAIN = 3;
    /** The survey versions QGroundControl reads (SurveyComplexItem::load); 4 and 5 carry their expanded items. */
    static final int SURVEY_MIN_VERSION = 2;
    static final int SURVEY_MAX_VERSION = 5;

    private final List<MissionItem> items = new ArrayList<>();
    private final List<Integer> jumpIds = new ArrayList<>();
    private final List<String> paths = new ArrayList<>();
    private final String jumpIdKey;

    /** @param jumpIdKey the key that names an item for DO_JUMP: "doJumpId", or "id" in the first .mission files */
    private PlanItems(String jumpIdKey) {
        this.jumpIdKey = jumpIdKey;
    }

    /**
     * The items of a JSON array, numbered from {@code firstSeq}, DO_JUMP targets resolved.
     *
     * @param where the array's JSON path, for errors
     */
    static List<MissionItem> read(List<?> entries, int firstSeq, String jumpIdKey, String where) {
        PlanItems reader = new PlanItems(jumpIdKey);
        for (int i = 0; i < entries.size(); i++) {
            reader.entry(entries.get(i), firstSeq, where + "[" + i + "]");
        }
        return reader.resolveJumps(firstSeq);
    }

    private void entry(Object value, int firstSeq, String where) {
        Map<?, ?> entry = PlanJson.map(value, where);
        Object type = entry.get("type");
        if ("SimpleItem".equals(type) || "missionItem".equals(type)) {
            add(entry, firstSeq, where);
        } else if ("ComplexItem".equals(type)) {
            Object complexType = entry.get("complexItemType");
            if ("survey".equals(complexType)) {
                double version = PlanJson.version(entry.get("version"), where + ".version");
                if (version < SURVEY_MIN_VERSION || version > SURVEY_MAX_VERSION) {
                    throw new IllegalArgumentException(where + ": survey version " + ItemText.number((float) version)
                            + " is not one QGroundControl reads (" + SURVEY_MIN_VERSION + " to " + SURVEY_MAX_VERSION + ")");
                }
            }
            Object transect = entry.get("TransectStyleComplexItem");
            if (!(transect instanceof Map<?, ?> t) || !(t.get("Items") instanceof List<?> expanded)) {
                throw new IllegalArgumentException(where + ": ComplexItem '" + complexType + "' has no"
                        + " TransectStyleComplexItem.Items to import (only surveys and corridor scans saved by"
                        + " QGroundControl 3.5 or later carry their expanded items; open and save the plan in"
                        + " QGroundControl to add them)");
            }
            for (int k = 0; k < expanded.size(); k++) {
                String w = where + ".TransectStyleComplexItem.Items[" + k + "]";
                Map<?, ?> simple = PlanJson.map(expanded.get(k), w);
                if (!"SimpleItem".equals(simple.get("type"))) {
                    throw new IllegalArgumentException(w + ": expected a SimpleItem, found type " + simple.get("type"));
                }
                add(simple, firstSeq, w);
            }
        } else {
            throw new IllegalArgumentException(where + ": unknown item type " + (type == null ? "(none)" : "\"" + type + "\"")
                    + " (expected SimpleItem or ComplexItem)");
        }
    }

    private void add(Map<?, ?> item, int firstSeq, String where) {
        List<?> all = allParams(item, where);
        float[] p = params(all, where);
        int frame = PlanJson.integer(item.get("frame"), where + ".frame");
        float z = p[6];
        Object mode = item.get("AltitudeMode");
        if (mode instanceof Number m && m.intValue() == ALTITUDE_CALC_ABOVE_TERRAIN && Float.isNaN(z)) {
            if (!(item.get("Altitude") instanceof Number altitude)) {
                throw new IllegalArgumentException(where + ": the altitude is to be calculated above terrain, but the"
                        + " plan has neither the calculated altitude (params[6]) nor the height above terrain"
                        + " (Altitude); open the plan in QGroundControl with terrain data and save it again");
            }
            frame = MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT;
            z = altitude.floatValue();
        }
        Object autoContinue = item.get("autoContinue");
        if (autoContinue != null) {
            PlanJson.bool(autoContinue, where + ".autoContinue");
        }
        String pw = where + ".params";
        items.add(new MissionItem(firstSeq + items.size(), PlanJson.integer(item.get("command"), where + ".command"),
                ItemText.itemFrame(frame), p[0], p[1], p[2], p[3],
                PlanJson.degE7(all.get(4), 90, pw + "[4] (latitude)"),
                PlanJson.degE7(all.get(5), 180, pw + "[5] (longitude)"), z,
                autoContinue == null || Boolean.TRUE.equals(autoContinue)));
        Object jumpId = item.get(jumpIdKey);
        jumpIds.add(jumpId == null ? null : PlanJson.integer(jumpId, where + "." + jumpIdKey));
        paths.add(where);
    }

    /** Params 1 to 4 and 7 as floats (5 and 6, degrees, are read exactly as degE7 by the caller). */
    private static float[] params(List<?> all, String where) {
        String pw = where + ".params";
        float[] p = new float[7];
        for (int i = 0; i < 7; i++) {
            if (i == 4 || i == 5) {
                continue;
            }
            p[i] = PlanJson.toFloat(all.get(i), pw + "[" + i + "]");
        }
        return p;
    }

    /** The seven params of any form: params[7], or params[4] / param1..param4 and coordinate [lat, lon, alt]. */
    private static List<?> allParams(Map<?, ?> item, String where) {
        List<Object> all = new ArrayList<>();
        Object params = item.get("params");
        if (params == null) {
            for (int i = 1; i <= 4; i++) {
                if (!item.containsKey("param" + i)) {
                    throw new IllegalArgumentException(where + ": expected \"params\" (or \"param1\" to \"param4\")");
                }
                all.add(item.get("param" + i));
            }
        } else {
            all.addAll(PlanJson.list(params, where + ".params"));
        }
        Object coordinate = item.get("coordinate");
        if (coordinate != null || all.size() == 4) {
            List<?> c = PlanJson.list(coordinate, where + ".coordinate");
            if (all.size() != 4 || c.size() != 3) {
                throw new IllegalArgumentException(where + ": an item with a coordinate [lat, lon, alt] has 4 params, found "
                        + all.size() + " params and " + c.size() + " coordinate values");
            }
            all.addAll(c);
        }
        if (all.size() != 7) {
            throw new IllegalArgumentException(where + ".params must have 7 values, found " + all.size());
        }
        return all;
    }

    /** DO_JUMP's param1 from the target's jump id to its item number, when the file names items by jump id. */
    private List<MissionItem> resolveJumps(int firstSeq) {
        if (jumpIds.stream().allMatch(id -> id == null)) {
            return items;
        }
        List<MissionItem> resolved = new ArrayList<>(items);
        for (int i = 0; i < items.size(); i++) {
            MissionItem it = items.get(i);
            if (it.command() != MAV_CMD.MAV_CMD_DO_JUMP) {
                continue;
            }
            float target = it.param1();
            int seq = jumpIds.indexOf(target == Math.rint(target) ? (int) target : Integer.MIN_VALUE);
            if (seq < 0) {
                throw new IllegalArgumentException(paths.get(i) + ": DO_JUMP to " + jumpIdKey + " "
                        + ItemText.number(target) + ", which no item of the mission has");
            }
            resolved.set(i, new MissionItem(it.seq(), it.command(), it.frame(), firstSeq + seq, it.param2(), it.param3(),
                    it.param4(), it.x(), it.y(), it.z(), it.autocontinue()));
        }
        return resolved;
    }
}
