package dolphin.mavlink.mission;

import groovy.json.JsonGenerator;
import groovy.json.JsonOutput;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A mission as GeoJSON (RFC 7946), to look at on a map (geojson.io, QGIS, GitHub's file view): a
 * FeatureCollection with a Point for each item that has a position, and a LineString through those
 * points in mission order, the flight path from the home. Export only.
 *
 * <p>Coordinates are [longitude, latitude, altitude] (GeoJSON's order), in degrees and metres as the
 * items carry them (AMSL in MAV_FRAME_GLOBAL_INT). A Point's properties are {@code seq},
 * {@code command} (the MAV_CMD name without its prefix), {@code frame} (the MAV_FRAME name) and
 * {@code params} [p1, p2, p3, p4] (NaN as null); the home point also has {@code "home": true}.
 * An item has a position when its frame is a global one and its latitude and longitude are not
 * both 0 (ArduPilot's "no position"). The collection carries the mission's name as {@code name}.
 */
public final class GeoJsonFile {

    public static final String EXTENSION = ".geojson";

    private static final JsonGenerator JSON = new JsonGenerator.Options().disableUnicodeEscaping().build();

    private GeoJsonFile() {
    }

    /** The GeoJSON of a mission's items, item 0 the home (as {@link Mission#items} gives them). */
    public static String write(String name, List<MissionItem> items) {
        FileValues.requireHome(items);
        List<Object> features = new ArrayList<>();
        List<Object> path = new ArrayList<>();
        for (int i = 0; i < items.size(); i++) {
            MissionItem it = items.get(i);
            if (!hasPosition(it)) {
                continue;
            }
            List<Object> coordinates = Arrays.asList(degrees(it.y()), degrees(it.x()), number(it.z()));
            path.add(coordinates);
            Map<String, Object> properties = new LinkedHashMap<>();
            properties.put("seq", i);
            properties.put("command", it.commandName());
            properties.put("frame", it.frameName());
            properties.put("params", Arrays.asList(number(it.param1()), number(it.param2()), number(it.param3()),
                    number(it.param4())));
            if (i == 0) {
                properties.put("home", true);
            }
            features.add(feature(FileValues.ordered("type", "Point", "coordinates", coordinates), properties));
        }
        if (path.size() >= 2) {
            Map<String, Object> properties = new LinkedHashMap<>();
            properties.put("name", name);
            properties.put("path", "flight path");
            features.add(feature(FileValues.ordered("type", "LineString", "coordinates", path), properties));
        }
        Map<String, Object> collection = new LinkedHashMap<>();
        collection.put("type", "FeatureCollection");
        collection.put("name", name);
        collection.put("features", features);
        return JsonOutput.prettyPrint(JSON.toJson(collection)) + "\n";
    }

    public static void write(Path file, String name, List<MissionItem> items) throws IOException {
        Files.writeString(file, write(name, items), StandardCharsets.UTF_8);
    }

    /** True when the item is at a place: a global frame, and not latitude 0 and longitude 0. */
    public static boolean hasPosition(MissionItem it) {
        return FileValues.isGlobal(it.frame()) && !(it.x() == 0 && it.y() == 0);
    }

    private static Map<String, Object> feature(Map<String, Object> geometry, Map<String, Object> properties) {
        Map<String, Object> f = new LinkedHashMap<>();
        f.put("type", "Feature");
        f.put("geometry", geometry);
        f.put("properties", properties);
        return f;
    }

    private static Object number(float f) {
        return FileValues.jsonNumber(f);
    }

    private static Object degrees(int degE7) {
        return FileValues.jsonDegrees(degE7);
    }
}
