package dolphin.mavlink.mission;

import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_TYPE;
import groovy.json.JsonException;
import groovy.json.JsonGenerator;
import groovy.json.JsonOutput;
import groovy.json.JsonSlurper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * QGroundControl's {@code .plan} (JSON): {@code {"fileType": "Plan", "version": 1, "groundStation",
 * "mission": {"version": 2, "firmwareType": 3 (ArduPilot), "vehicleType", "cruiseSpeed", "hoverSpeed",
 * "plannedHomePosition": [lat, lon, alt], "items": [...]}, "geoFence", "rallyPoints"}}.
 *
 * <p>The home (item 0) is {@code plannedHomePosition}; the other items are {@code SimpleItem}s
 * {@code {"type", "command", "frame", "params": [p1, p2, p3, p4, lat, lon, alt], "autoContinue",
 * "doJumpId": seq}}, with latitude and longitude in degrees (exactly the item's degE7) and the float
 * frames (see {@link FileValues}). NaN parameters are {@code null}, as QGroundControl writes them
 * (an infinity, which JSON cannot carry either, is null too and reads back as NaN).
 *
 * <p>Reading flattens {@code ComplexItem}s (survey, corridor scan) into the SimpleItems QGroundControl
 * pre-expanded in {@code TransectStyleComplexItem.Items}, and ignores the geofence and rally points.
 */
public final class PlanFile {

    public static final String EXTENSION = ".plan";
    public static final String GROUND_STATION = "Dolphin";
    /** QGroundControl's defaults for a new plan, in m/s. */
    public static final double CRUISE_SPEED = 15;
    public static final double HOVER_SPEED = 5;

    private static final JsonGenerator JSON = new JsonGenerator.Options().disableUnicodeEscaping().build();

    private PlanFile() {
    }

    /** The plan of a copter mission (vehicleType MAV_TYPE_QUADROTOR). */
    public static String write(List<MissionItem> items) {
        return write(items, MAV_TYPE.MAV_TYPE_QUADROTOR);
    }

    /**
     * The file's JSON for the items of a mission, item 0 the home (as {@link Mission#items} gives them).
     *
     * @param vehicleType a MAV_TYPE, which QGroundControl uses to pick its vehicle profile
     */
    public static String write(List<MissionItem> items, int vehicleType) {
        FileValues.requireHome(items);
        MissionItem home = items.get(0);
        List<Object> simpleItems = new ArrayList<>();
        for (int i = 1; i < items.size(); i++) {
            MissionItem it = items.get(i);
            Map<String, Object> item = new LinkedHashMap<>();
            item.put("type", "SimpleItem");
            item.put("command", it.command());
            item.put("frame", FileValues.fileFrame(it.frame()));
            item.put("params", Arrays.asList(number(it.param1()), number(it.param2()), number(it.param3()),
                    number(it.param4()), degrees(it.x()), degrees(it.y()), number(it.z())));
            item.put("autoContinue", it.autocontinue());
            item.put("doJumpId", i);
            simpleItems.add(item);
        }
        Map<String, Object> mission = new LinkedHashMap<>();
        mission.put("version", 2);
        mission.put("firmwareType", MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA);
        mission.put("vehicleType", vehicleType);
        mission.put("cruiseSpeed", CRUISE_SPEED);
        mission.put("hoverSpeed", HOVER_SPEED);
        mission.put("plannedHomePosition", Arrays.asList(degrees(home.x()), degrees(home.y()), number(home.z())));
        mission.put("items", simpleItems);

        Map<String, Object> plan = new LinkedHashMap<>();
        plan.put("fileType", "Plan");
        plan.put("version", 1);
        plan.put("groundStation", GROUND_STATION);
        plan.put("mission", mission);
        plan.put("geoFence", FileValues.ordered("version", 2, "polygons", List.of(), "circles", List.of()));
        plan.put("rallyPoints", FileValues.ordered("version", 2, "points", List.of()));
        return JsonOutput.prettyPrint(JSON.toJson(plan)) + "\n";
    }

    public static void write(Path file, List<MissionItem> items) throws IOException {
        Files.writeString(file, write(items), StandardCharsets.UTF_8);
    }

    /**
     * The items of a plan: item 0 a NAV_WAYPOINT at {@code plannedHomePosition} (the home item
     * {@link Mission#items} makes), then the SimpleItems, the ComplexItems' pre-expanded items
     * flattened in place, numbered from 1 in file order.
     *
     * @throws IllegalArgumentException saying what is wrong, for a text that is not such a plan
     */
    public static List<MissionItem> read(String text) {
        Object root;
        try {
            root = new JsonSlurper().parseText(MissionFileText.withoutBom(text));
        } catch (JsonException | IllegalArgumentException e) {
            throw new IllegalArgumentException("not a QGroundControl plan: the text is not JSON (" + oneLine(e) + ")", e);
        }
        if (!(root instanceof Map<?, ?> plan) || !"Plan".equals(plan.get("fileType"))) {
            throw new IllegalArgumentException("not a QGroundControl plan: \"fileType\" must be \"Plan\"");
        }
        Map<?, ?> mission = map(plan.get("mission"), "mission");
        List<?> home = list(mission.get("plannedHomePosition"), "mission.plannedHomePosition");
        if (home.size() != 3) {
            throw new IllegalArgumentException("mission.plannedHomePosition must be [lat, lon, alt], found " + home);
        }
        List<MissionItem> items = new ArrayList<>();
        items.add(new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MissionItem.GLOBAL_INT, 0, 0, 0, 0,
                degE7(home.get(0), "plannedHomePosition"), degE7(home.get(1), "plannedHomePosition"),
                toFloat(home.get(2), "plannedHomePosition"), true));
        List<?> entries = list(mission.get("items"), "mission.items");
        for (int i = 0; i < entries.size(); i++) {
            String where = "mission.items[" + i + "]";
            Map<?, ?> entry = map(entries.get(i), where);
            Object type = entry.get("type");
            if ("SimpleItem".equals(type)) {
                items.add(simpleItem(entry, items.size(), where));
            } else if ("ComplexItem".equals(type)) {
                Object transect = entry.get("TransectStyleComplexItem");
                if (!(transect instanceof Map<?, ?> t) || !(t.get("Items") instanceof List<?> expanded)) {
                    throw new IllegalArgumentException(where + ": ComplexItem '" + entry.get("complexItemType")
                            + "' has no TransectStyleComplexItem.Items to import (only surveys and corridor scans"
                            + " saved by QGroundControl carry their expanded items)");
                }
                for (int k = 0; k < expanded.size(); k++) {
                    String w = where + ".TransectStyleComplexItem.Items[" + k + "]";
                    items.add(simpleItem(map(expanded.get(k), w), items.size(), w));
                }
            } else {
                throw new IllegalArgumentException(where + ": unknown item type " + type
                        + " (expected SimpleItem or ComplexItem)");
            }
        }
        return items;
    }

    /** The items of a file, UTF-8 with or without a byte-order mark; errors name the file. */
    public static List<MissionItem> read(Path file) throws IOException {
        return MissionFileText.parse(file, PlanFile::read);
    }

    /** The parser's first line and the line it stopped at: its message also dumps the text around it. */
    private static String oneLine(RuntimeException e) {
        String message = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        String first = message.lines().findFirst().orElse("").strip();
        Matcher line = Pattern.compile("line number (\\d+)").matcher(message);
        return line.find() ? first + ", at line " + line.group(1) : first;
    }

    private static MissionItem simpleItem(Map<?, ?> item, int seq, String where) {
        if (!"SimpleItem".equals(item.get("type"))) {
            throw new IllegalArgumentException(where + ": expected a SimpleItem, found type " + item.get("type"));
        }
        List<?> p = list(item.get("params"), where + ".params");
        if (p.size() != 7) {
            throw new IllegalArgumentException(where + ".params must have 7 values, found " + p.size());
        }
        String pw = where + ".params";
        Object autoContinue = item.get("autoContinue");
        return new MissionItem(seq, integer(item.get("command"), where + ".command"),
                FileValues.itemFrame(integer(item.get("frame"), where + ".frame")),
                toFloat(p.get(0), pw), toFloat(p.get(1), pw), toFloat(p.get(2), pw), toFloat(p.get(3), pw),
                degE7(p.get(4), pw), degE7(p.get(5), pw), toFloat(p.get(6), pw),
                autoContinue == null || Boolean.TRUE.equals(autoContinue));
    }

    private static Object number(float f) {
        return FileValues.jsonNumber(f);
    }

    private static Object degrees(int degE7) {
        return FileValues.jsonDegrees(degE7);
    }

    private static float toFloat(Object v, String where) {
        if (v == null) {
            return Float.NaN;
        }
        if (!(v instanceof Number)) {
            throw new IllegalArgumentException(where + ": expected a number or null, found " + v);
        }
        return FileValues.parseFloat(v.toString());
    }

    private static int degE7(Object v, String where) {
        if (v == null) {
            return 0;
        }
        if (!(v instanceof Number)) {
            throw new IllegalArgumentException(where + ": expected degrees, found " + v);
        }
        try {
            return FileValues.degE7(v.toString());
        } catch (NumberFormatException | ArithmeticException e) {
            throw new IllegalArgumentException(where + ": " + e.getMessage(), e);
        }
    }

    private static int integer(Object v, String where) {
        if (!(v instanceof Number n)) {
            throw new IllegalArgumentException(where + ": expected an integer, found " + v);
        }
        try {
            return FileValues.parseInt(n.toString());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(where + ": " + e.getMessage(), e);
        }
    }

    private static Map<?, ?> map(Object v, String where) {
        if (!(v instanceof Map<?, ?> m)) {
            throw new IllegalArgumentException(where + ": expected a JSON object, found " + (v == null ? "nothing" : v));
        }
        return m;
    }

    private static List<?> list(Object v, String where) {
        if (!(v instanceof List<?> l)) {
            throw new IllegalArgumentException(where + ": expected a JSON array, found " + (v == null ? "nothing" : v));
        }
        return l;
    }
}
