package dolphin.mission.file;

import dolphin.core.Position;
import dolphin.mission.model.ItemText;
import dolphin.mission.model.Fence;
import dolphin.mission.model.FenceRegion;
import dolphin.mission.model.Mission;
import dolphin.mission.model.MissionItem;
import dolphin.mission.survey.Coverage;
import dolphin.mission.survey.MappingItem;
import dolphin.mission.survey.PhotoGrid;
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
import java.util.TreeMap;

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
 *
 * <p>A fence adds a Polygon for each polygon region and for each circle (GeoJSON has no circle: a
 * ring of {@value #CIRCLE_SEGMENTS} points, with {@code radius} and {@code center} in its
 * properties), each with {@code "fence": "inclusion"} or {@code "exclusion"}, and a Point for its
 * return point ({@code "fence": "return point"}); rally points are Points with {@code "rally": n}.
 *
 * <p>Each mapping item of the file (a survey, corridor or structure scan) adds its outline, a
 * Polygon (a LineString for a corridor's path) with {@code kind} (QGroundControl's complex item
 * type), {@code word}, {@code seq} (its first item), {@code altitude}, {@code gsd} (cm/px; null
 * without a camera), {@code photos}, {@code spacing} and {@code triggerDistance} (m), and its photos'
 * ground footprints as one MultiPolygon ({@code "footprints": word}): a single feature keeps a
 * survey of thousands of photos a small file that map viewers still draw at once.
 */
public final class GeoJsonFile {

    public static final String EXTENSION = ".geojson";

    private static final JsonGenerator JSON = new JsonGenerator.Options().disableUnicodeEscaping().build();

    private GeoJsonFile() {
    }

    /** Segments of the ring drawn for a fence circle. */
    static final int CIRCLE_SEGMENTS = 64;

    /** The GeoJSON of a mission's items, item 0 the home (as {@link Mission#items} gives them). */
    public static String write(String name, List<MissionItem> items) {
        FileValues.requireHome(items);
        return write(name, MissionFile.of(items));
    }

    /** The GeoJSON of a mission (if any) with its fence and rally points, indented for a file. */
    public static String write(String name, MissionFile file) {
        return JsonOutput.prettyPrint(compact(name, file)) + "\n";
    }

    /** The same GeoJSON on one line, for a stream (the web view's). */
    public static String compact(String name, MissionFile file) {
        List<MissionItem> items = file.mission();
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
        addMappingItems(file, features);
        addFence(file.fence(), features);
        for (MissionItem it : file.rally().items()) {
            features.add(feature(FileValues.ordered("type", "Point", "coordinates",
                    Arrays.asList(degrees(it.y()), degrees(it.x()), number(it.z()))),
                    FileValues.ordered("rally", it.seq(), "frame", it.frameName())));
        }
        Map<String, Object> collection = new LinkedHashMap<>();
        collection.put("type", "FeatureCollection");
        collection.put("name", name);
        collection.put("features", features);
        return JSON.toJson(collection);
    }

    public static void write(Path file, String name, List<MissionItem> items) throws IOException {
        Files.writeString(file, write(name, items), StandardCharsets.UTF_8);
    }

    /** Each mapping item's outline with its numbers, then its photo footprints as one MultiPolygon. */
    private static void addMappingItems(MissionFile file, List<Object> features) {
        for (Map.Entry<Integer, MappingItem> e : new TreeMap<>(file.mappingItems()).entrySet()) {
            MappingItem m = e.getValue();
            List<Object> outline = new ArrayList<>();
            m.outline().forEach(v -> outline.add(lonLat(v)));
            Map<String, Object> geometry;
            if (m.closedOutline()) {
                outline.add(outline.get(0)); // GeoJSON closes its rings
                geometry = FileValues.ordered("type", "Polygon", "coordinates", List.of(outline));
            } else {
                geometry = FileValues.ordered("type", "LineString", "coordinates", outline);
            }
            PhotoGrid grid = m.photoGrid();
            Coverage coverage = m.coverage();
            features.add(feature(geometry, FileValues.ordered("kind", m.qgcType(), "word", m.name(), "seq", e.getKey(),
                    "altitude", FileValues.jsonDouble(grid.altitude()), "gsd", FileValues.jsonDouble(coverage.gsd()),
                    "photos", coverage.photos(), "spacing", FileValues.jsonDouble(grid.spacing()),
                    "triggerDistance", FileValues.jsonDouble(grid.triggerDistance()))));
            List<List<Position>> footprints = m.footprints();
            if (footprints.isEmpty()) {
                continue;
            }
            List<Object> polygons = new ArrayList<>();
            for (List<Position> corners : footprints) {
                List<Object> ring = new ArrayList<>();
                corners.forEach(c -> ring.add(lonLat(c)));
                ring.add(ring.get(0));
                polygons.add(List.of(ring));
            }
            features.add(feature(FileValues.ordered("type", "MultiPolygon", "coordinates", polygons),
                    FileValues.ordered("footprints", m.name(), "seq", e.getKey(), "photos", footprints.size())));
        }
    }

    private static void addFence(Fence fence, List<Object> features) {
        for (FenceRegion r : fence.regions()) {
            String kind = r.inclusion() ? "inclusion" : "exclusion";
            List<Object> ring = new ArrayList<>();
            Map<String, Object> properties = FileValues.ordered("fence", kind);
            if (r instanceof FenceRegion.Polygon p) {
                p.vertices().forEach(v -> ring.add(lonLat(v)));
                properties.put("shape", "polygon");
            } else if (r instanceof FenceRegion.Circle c) {
                for (int k = 0; k < CIRCLE_SEGMENTS; k++) {
                    double bearing = 2 * Math.PI * k / CIRCLE_SEGMENTS;
                    ring.add(lonLat(c.center().displace(c.radius() * Math.cos(bearing), c.radius() * Math.sin(bearing), 0)));
                }
                properties.put("shape", "circle");
                properties.put("center", lonLat(c.center()));
                properties.put("radius", number((float) c.radius()));
            }
            ring.add(ring.get(0)); // GeoJSON closes its rings
            features.add(feature(FileValues.ordered("type", "Polygon", "coordinates", List.of(ring)), properties));
        }
        fence.items().stream().filter(it -> it.command() == com.MAVLink.enums.MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT)
                .forEach(it -> features.add(feature(FileValues.ordered("type", "Point", "coordinates",
                        Arrays.asList(degrees(it.y()), degrees(it.x()), number(it.z()))),
                        FileValues.ordered("fence", "return point", "frame", it.frameName()))));
    }

    private static List<Object> lonLat(Position p) {
        return Arrays.asList(degrees(MissionItem.degE7(p.longitudeDegrees())), degrees(MissionItem.degE7(p.latitudeDegrees())));
    }

    /** True when the item is at a place: a global frame, and not latitude 0 and longitude 0. */
    public static boolean hasPosition(MissionItem it) {
        return ItemText.isGlobal(it.frame()) && !(it.x() == 0 && it.y() == 0);
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
