package dolphin.mission.file;

import dolphin.mission.model.ItemText;
import dolphin.mission.model.Fence;
import dolphin.mission.model.Mission;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.RallyPoints;
import dolphin.mission.model.VehicleProfile;
import dolphin.mission.survey.MappingItem;
import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_CMD;
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
 * "plannedHomePosition": [lat, lon, alt], "items": [...]}, "geoFence", "rallyPoints"}}, and the older
 * QGroundControl files it grew from (docs/mission-files.md).
 *
 * <p>The home (item 0) is {@code plannedHomePosition}; the other items are {@code SimpleItem}s
 * {@code {"type", "command", "frame", "params": [p1, p2, p3, p4, lat, lon, alt], "autoContinue",
 * "doJumpId": seq}}, with latitude and longitude in degrees (exactly the item's degE7) and the float
 * frames (see {@link FileValues}). NaN parameters are {@code null}, as QGroundControl writes them
 * (an infinity, which JSON cannot carry either, is null too and reads back as NaN). Items are read
 * by {@link PlanItems}, the geofence and rally points by {@link PlanAirspace}.
 *
 * <p>Versions are checked with the numbers QGroundControl accepts: a plan of version 1 whose mission
 * is of version 2; a {@code .mission} of fileType "Mission" and version 2 (QGroundControl 3.x, the
 * mission object at the root); the first {@code .mission} files, without fileType and of version "1.0".
 */
public final class PlanFile {

    public static final String EXTENSION = ".plan";
    public static final String GROUND_STATION = "Dolphin";
    public static final int PLAN_VERSION = 1;
    public static final int MISSION_VERSION = 2;

    private static final JsonGenerator JSON = new JsonGenerator.Options().disableUnicodeEscaping().build();

    private PlanFile() {
    }

    /** The plan of a copter mission without fence or rally points. */
    public static String write(List<MissionItem> items) {
        return write(MissionFile.of(items));
    }

    /**
     * The file's JSON: the mission (item 0 the home, as {@link Mission#items} gives them), its
     * fence and rally points, and the vehicle profile (firmware, vehicle type, speeds). A file
     * without a mission gets its first fence or rally position as the planned home, at height 0.
     * The file's mapping items become ComplexItems that QGroundControl opens as editable surveys
     * ({@link PlanComplexItems}); the other items SimpleItems.
     *
     * @throws IllegalArgumentException when a mapping item's items are not the mission's at its seq
     */
    public static String write(MissionFile file) {
        List<MissionItem> items = file.mission();
        MissionItem home = items.isEmpty() ? airspaceHome(file) : items.get(0);
        List<Object> simpleItems = new ArrayList<>();
        for (int i = 1; i < items.size(); i++) {
            MappingItem complex = file.mappingItems().get(i);
            if (complex == null) {
                simpleItems.add(simpleItem(items.get(i), i));
                continue;
            }
            List<MissionItem> own = complex.items(i);
            List<MissionItem> expanded = items.subList(i, Math.min(items.size(), i + own.size()));
            if (!expanded.equals(own)) {
                throw new IllegalArgumentException("item " + i + ": the mission's items are not those of its "
                        + complex.qgcType() + " '" + complex.name() + "', which starts there");
            }
            simpleItems.add(PlanComplexItems.write(complex, expanded));
            i += expanded.size() - 1;
        }
        VehicleProfile v = file.vehicle();
        Map<String, Object> mission = new LinkedHashMap<>();
        mission.put("version", MISSION_VERSION);
        mission.put("firmwareType", v.firmwareType());
        mission.put("vehicleType", v.vehicleType());
        mission.put("cruiseSpeed", JsonOutput.unescaped(ItemText.number((float) v.cruiseSpeed())));
        mission.put("hoverSpeed", JsonOutput.unescaped(ItemText.number((float) v.hoverSpeed())));
        mission.put("plannedHomePosition", Arrays.asList(degrees(home.x()), degrees(home.y()), number(home.z())));
        mission.put("items", simpleItems);

        Map<String, Object> plan = new LinkedHashMap<>();
        plan.put("fileType", "Plan");
        plan.put("version", PLAN_VERSION);
        plan.put("groundStation", GROUND_STATION);
        plan.put("mission", mission);
        plan.put("geoFence", PlanAirspace.writeFence(file.fence(), home));
        plan.put("rallyPoints", PlanAirspace.writeRally(file.rally(), home));
        return JsonOutput.prettyPrint(JSON.toJson(plan)) + "\n";
    }

    /** A SimpleItem as QGroundControl writes it; {@code doJumpId} the item's seq, which DO_JUMP targets name. */
    static Map<String, Object> simpleItem(MissionItem it, int doJumpId) {
        Map<String, Object> item = new LinkedHashMap<>();
        item.put("type", "SimpleItem");
        item.put("command", it.command());
        item.put("frame", ItemText.fileFrame(it.frame()));
        item.put("params", Arrays.asList(number(it.param1()), number(it.param2()), number(it.param3()),
                number(it.param4()), degrees(it.x()), degrees(it.y()), number(it.z())));
        item.put("autoContinue", it.autocontinue());
        item.put("doJumpId", doJumpId);
        return item;
    }

    public static void write(Path file, List<MissionItem> items) throws IOException {
        Files.writeString(file, write(items), StandardCharsets.UTF_8);
    }

    /**
     * The items of a plan: item 0 a NAV_WAYPOINT at {@code plannedHomePosition} (the home item
     * {@link Mission#items} makes), then the SimpleItems and the ComplexItems' items in place (those
     * QGroundControl stored, else regenerated: {@link PlanItems}), numbered from 1 in file order.
     *
     * @throws IllegalArgumentException saying what is wrong, for a text that is not such a plan
     */
    public static List<MissionItem> read(String text) {
        return readFile(text).mission();
    }

    /**
     * Everything a plan (or an older QGroundControl mission file) holds.
     *
     * @throws IllegalArgumentException saying what is wrong and where (the JSON path), for a text
     *         that is not such a file
     */
    public static MissionFile readFile(String text) {
        Object root;
        try {
            root = new JsonSlurper().parseText(MissionFileText.withoutBom(text));
        } catch (JsonException | IllegalArgumentException e) {
            throw new IllegalArgumentException("not a QGroundControl plan: the text is not JSON (" + oneLine(e) + ")", e);
        }
        if (!(root instanceof Map<?, ?> json)) {
            throw new IllegalArgumentException("not a QGroundControl plan: the JSON is not an object");
        }
        Object fileType = json.get("fileType");
        if ("Plan".equals(fileType)) {
            requireVersion(json, PLAN_VERSION, "version", "plans");
            Map<?, ?> mission = PlanJson.map(json.get("mission"), "mission");
            requireVersion(mission, MISSION_VERSION, "mission.version", "plan missions");
            return mission(mission, "mission.")
                    .withFence(PlanAirspace.readFence(json.get("geoFence")))
                    .withRally(PlanAirspace.readRally(json.get("rallyPoints")));
        }
        if ("Mission".equals(fileType)) {
            requireVersion(json, MISSION_VERSION, "version", ".mission files");
            return mission(json, "");
        }
        if (fileType == null && json.containsKey("MAV_AUTOPILOT")) {
            return firstMissionFormat(json);
        }
        throw new IllegalArgumentException("not a QGroundControl plan: \"fileType\" must be \"Plan\""
                + (fileType == null ? ", the file has none" : ", found " + fileType));
    }

    /** The items of a file, UTF-8 with or without a byte-order mark; errors name the file. */
    public static List<MissionItem> read(Path file) throws IOException {
        return MissionFileText.parse(file, PlanFile::read);
    }

    /** Everything a file holds, UTF-8 with or without a byte-order mark; errors name the file. */
    public static MissionFile readFile(Path file) throws IOException {
        return MissionFileText.parse(file, PlanFile::readFile);
    }

    /** A mission object of version 2 (a plan's "mission", or a .mission file's root). */
    private static MissionFile mission(Map<?, ?> mission, String prefix) {
        List<?> home = PlanJson.list(mission.get("plannedHomePosition"), prefix + "plannedHomePosition");
        if (home.size() != 3) {
            throw new IllegalArgumentException(prefix + "plannedHomePosition must be [lat, lon, alt], found " + home);
        }
        String hw = prefix + "plannedHomePosition";
        List<MissionItem> items = new ArrayList<>();
        items.add(new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MissionItem.GLOBAL_INT, 0, 0, 0, 0,
                PlanJson.degE7(home.get(0), 90, hw + "[0]"), PlanJson.degE7(home.get(1), 180, hw + "[1]"),
                PlanJson.toFloat(home.get(2), hw + "[2]"), true));
        items.addAll(PlanItems.read(PlanJson.list(mission.get("items"), prefix + "items"), 1, "doJumpId", prefix + "items"));
        VehicleProfile defaults = VehicleProfile.ARDUPILOT_COPTER;
        VehicleProfile vehicle = new VehicleProfile(
                optionalInt(mission, "firmwareType", defaults.firmwareType(), prefix),
                optionalInt(mission, "vehicleType", defaults.vehicleType(), prefix),
                optionalDouble(mission, "cruiseSpeed", defaults.cruiseSpeed(), prefix),
                optionalDouble(mission, "hoverSpeed", defaults.hoverSpeed(), prefix));
        return new MissionFile(items, Fence.NONE, RallyPoints.NONE, vehicle);
    }

    /**
     * QGroundControl's first .mission files: {@code {"version": "1.0", "MAV_AUTOPILOT",
     * "plannedHomePosition": {a missionItem}, "items": [{"type": "missionItem", "id", "param1".."param4",
     * "coordinate"}], "complexItems": []}}. Their surveys carry no expanded items and are refused.
     */
    private static MissionFile firstMissionFormat(Map<?, ?> json) {
        double version = PlanJson.version(json.get("version"), "version");
        if (version != 1) {
            throw new IllegalArgumentException("version " + json.get("version") + ": QGroundControl's .mission files"
                    + " without fileType are of version 1.0");
        }
        Object complex = json.get("complexItems");
        if (complex != null && !PlanJson.list(complex, "complexItems").isEmpty()) {
            throw new IllegalArgumentException("complexItems: the surveys of a version 1.0 .mission file carry no"
                    + " expanded items to import; open the file in QGroundControl and save it as a plan");
        }
        List<MissionItem> home = PlanItems.read(List.of(PlanJson.map(json.get("plannedHomePosition"),
                "plannedHomePosition")), 0, "id", "plannedHomePosition");
        MissionItem h = home.get(0);
        List<MissionItem> items = new ArrayList<>();
        items.add(new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MissionItem.GLOBAL_INT, 0, 0, 0, 0, h.x(), h.y(),
                h.z(), true));
        items.addAll(PlanItems.read(PlanJson.list(json.get("items"), "items"), 1, "id", "items"));
        int firmware = optionalInt(json, "MAV_AUTOPILOT", MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA, "");
        return new MissionFile(items, Fence.NONE, RallyPoints.NONE, new VehicleProfile(firmware,
                VehicleProfile.ARDUPILOT_COPTER.vehicleType(), VehicleProfile.CRUISE_SPEED, VehicleProfile.HOVER_SPEED));
    }

    private static void requireVersion(Map<?, ?> json, int expected, String where, String what) {
        Object v = json.get(where.substring(where.lastIndexOf('.') + 1));
        if (v == null) {
            throw new IllegalArgumentException(where + ": missing; QGroundControl " + what + " are of version " + expected);
        }
        double version = PlanJson.version(v, where);
        if (version != expected) {
            throw new IllegalArgumentException(where + " " + v + " is not one QGroundControl reads: its " + what
                    + " are of version " + expected);
        }
    }

    private static int optionalInt(Map<?, ?> json, String key, int fallback, String prefix) {
        return json.get(key) == null ? fallback : PlanJson.integer(json.get(key), prefix + key);
    }

    private static double optionalDouble(Map<?, ?> json, String key, double fallback, String prefix) {
        return json.get(key) == null ? fallback : PlanJson.toDouble(json.get(key), prefix + key);
    }

    /** A planned home for a file of only a fence or rally points: their first position, at height 0. */
    private static MissionItem airspaceHome(MissionFile file) {
        List<MissionItem> points = new ArrayList<>(file.fence().items());
        points.addAll(file.rally().items());
        if (points.isEmpty()) {
            throw new IllegalArgumentException("a plan needs a mission, a fence or rally points: the file has none");
        }
        MissionItem first = points.get(0);
        return new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MissionItem.GLOBAL_INT, 0, 0, 0, 0, first.x(), first.y(),
                0, true);
    }

    /** The parser's first line and the line it stopped at: its message also dumps the text around it. */
    private static String oneLine(RuntimeException e) {
        String message = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        String first = message.lines().findFirst().orElse("").strip();
        Matcher line = Pattern.compile("line number (\\d+)").matcher(message);
        return line.find() ? first + ", at line " + line.group(1) : first;
    }

    private static Object number(float f) {
        return FileValues.jsonNumber(f);
    }

    private static Object degrees(int degE7) {
        return FileValues.jsonDegrees(degE7);
    }
}
