package dolphin.mission.file;

import dolphin.core.Position;
import dolphin.mission.model.MissionItem;
import dolphin.mission.survey.Camera;
import dolphin.mission.survey.Cameras;
import dolphin.mission.survey.CorridorScan;
import dolphin.mission.survey.EntryCorner;
import dolphin.mission.survey.Emission;
import dolphin.mission.survey.HeightReference;
import dolphin.mission.survey.MappingItem;
import dolphin.mission.survey.PhotoGrid;
import dolphin.mission.survey.PolygonSurvey;
import dolphin.mission.survey.StructureScan;
import dolphin.mission.survey.TransectOptions;
import dolphin.mission.survey.TransectPoint;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * QGroundControl's complex items (surveys, corridor scans, structure scans) as the survey engine's
 * {@link MappingItem}s, both ways, with the keys of docs/qgc-surveys.md §4.
 *
 * <p>Reading builds the item from what QGroundControl itself uses when it regenerates one: the
 * stored {@code CameraCalc} values ({@code DistanceToSurface}, {@code AdjustedFootprintSide},
 * {@code AdjustedFootprintFrontal}), which it does not recompute on load, and the distance mode.
 * "Calculate above terrain" needs QGroundControl's terrain tiles, so it is read as flying at the
 * distance above terrain in MAV_FRAME_GLOBAL_TERRAIN_ALT, which ArduPilot follows with its own
 * terrain data (as {@link PlanItems} reads uncomputed terrain altitudes).
 *
 * <p>Writing gives what QGroundControl saves: survey version 5, CorridorScan 2, StructureScan 3,
 * TransectStyleComplexItem 2 with CameraCalc 2, the expanded items as SimpleItems (none for a
 * structure scan, which QGroundControl regenerates on every load).
 */
final class PlanComplexItems {

    static final String SURVEY = "survey";
    static final String CORRIDOR = "CorridorScan";
    static final String STRUCTURE = "StructureScan";
    static final int SURVEY_VERSION = 5;
    static final int CORRIDOR_VERSION = 2;
    static final int STRUCTURE_VERSION = 3;
    static final int TRANSECT_STYLE_VERSION = 2;
    static final int CAMERA_CALC_VERSION = 2;

    /** QGroundControl's AltMode CalcAboveTerrain, after which it flies no refly pass. */
    private static final int MODE_CALC_ABOVE_TERRAIN = 3;

    private PlanComplexItems() {
    }

    /** True for the complex item types {@link #read} regenerates. */
    static boolean regenerates(Object complexItemType) {
        return SURVEY.equals(complexItemType) || CORRIDOR.equals(complexItemType) || STRUCTURE.equals(complexItemType);
    }

    /**
     * The mapping item a ComplexItem describes.
     *
     * @param where the item's JSON path, for errors
     * @throws IllegalArgumentException naming the JSON path of a missing or wrong key, or what the engine refused
     */
    static MappingItem read(Map<?, ?> entry, String where) {
        Object type = entry.get("complexItemType");
        int version = PlanJson.integer(entry.get("version"), where + ".version");
        try {
            if (SURVEY.equals(type)) {
                requireVersion(version, 4, SURVEY_VERSION, "survey", where);
                Map<?, ?> transect = PlanJson.map(entry.get("TransectStyleComplexItem"), where + ".TransectStyleComplexItem");
                String tw = where + ".TransectStyleComplexItem";
                Object alternate = entry.get("flyAlternateTransects");
                return new PolygonSurvey(SURVEY, vertices(entry.get("polygon"), where + ".polygon"),
                        grid(PlanJson.map(transect.get("CameraCalc"), tw + ".CameraCalc"), tw + ".CameraCalc"),
                        PlanJson.toDouble(entry.get("angle"), where + ".angle"),
                        corner(entry.get("entryLocation"), where + ".entryLocation"),
                        alternate != null && PlanJson.bool(alternate, where + ".flyAlternateTransects"),
                        options(transect, tw));
            }
            if (CORRIDOR.equals(type)) {
                requireVersion(version, CORRIDOR_VERSION, CORRIDOR_VERSION, "corridor scan", where);
                Map<?, ?> transect = PlanJson.map(entry.get("TransectStyleComplexItem"), where + ".TransectStyleComplexItem");
                String tw = where + ".TransectStyleComplexItem";
                return new CorridorScan(CORRIDOR, vertices(entry.get("polyline"), where + ".polyline"),
                        PlanJson.toDouble(entry.get("CorridorWidth"), where + ".CorridorWidth"),
                        grid(PlanJson.map(transect.get("CameraCalc"), tw + ".CameraCalc"), tw + ".CameraCalc"),
                        corner(entry.get("EntryPoint"), where + ".EntryPoint"), options(transect, tw));
            }
            requireVersion(version, STRUCTURE_VERSION, STRUCTURE_VERSION, "structure scan", where);
            return new StructureScan(STRUCTURE, vertices(entry.get("polygon"), where + ".polygon"),
                    grid(PlanJson.map(entry.get("CameraCalc"), where + ".CameraCalc"), where + ".CameraCalc"),
                    PlanJson.toDouble(entry.get("StructureHeight"), where + ".StructureHeight"),
                    PlanJson.toDouble(entry.get("ScanBottomAlt"), where + ".ScanBottomAlt"),
                    PlanJson.toDouble(entry.get("EntranceAltitude"), where + ".EntranceAltitude"),
                    PlanJson.bool(entry.get("StartFromTop"), where + ".StartFromTop"),
                    PlanJson.toDouble(entry.get("GimbalPitch"), where + ".GimbalPitch"));
        } catch (IllegalArgumentException e) {
            throw e.getMessage() != null && e.getMessage().startsWith(where) ? e
                    : new IllegalArgumentException(where + ": " + e.getMessage(), e);
        }
    }

    private static void requireVersion(int version, int min, int max, String what, String where) {
        if (version < min || version > max) {
            throw new IllegalArgumentException(where + ".version: a " + what + " of version " + version + " without expanded"
                    + " items cannot be regenerated (versions " + (min == max ? String.valueOf(min) : min + " to " + max)
                    + " can); open and save the plan in QGroundControl to store its items");
        }
    }

    private static List<Position> vertices(Object value, String where) {
        List<?> list = PlanJson.list(value, where);
        List<Position> vertices = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            String w = where + "[" + i + "]";
            List<?> c = PlanJson.list(list.get(i), w);
            if (c.size() != 2) {
                throw new IllegalArgumentException(w + ": expected [lat, lon], found " + c.size() + " values");
            }
            vertices.add(Position.fromDegrees(PlanJson.degrees(c.get(0), 90, w + "[0] (latitude)"),
                    PlanJson.degrees(c.get(1), 180, w + "[1] (longitude)"), 0));
        }
        return vertices;
    }

    private static EntryCorner corner(Object value, String where) {
        int n = PlanJson.integer(value, where);
        if (n < 0 || n >= EntryCorner.values().length) {
            throw new IllegalArgumentException(where + ": expected 0 to 3 (top left, top right, bottom left, bottom right),"
                    + " found " + n);
        }
        return EntryCorner.values()[n];
    }

    /**
     * The CameraCalc's stored values as a photo grid. A camera whose numbers the engine refuses (QGroundControl
     * saves zeros when its recalculation got stuck, docs/qgc-surveys.md §0.8) is read as Manual: the items
     * depend only on the stored distance, spacing and trigger distance.
     */
    private static PhotoGrid grid(Map<?, ?> calc, String where) {
        double altitude = PlanJson.toDouble(calc.get("DistanceToSurface"), where + ".DistanceToSurface");
        double spacing = PlanJson.toDouble(calc.get("AdjustedFootprintSide"), where + ".AdjustedFootprintSide");
        double trigger = PlanJson.toDouble(calc.get("AdjustedFootprintFrontal"), where + ".AdjustedFootprintFrontal");
        Object name = calc.get("CameraName");
        if (!(name instanceof String cameraName)) {
            throw new IllegalArgumentException(where + ".CameraName: expected a camera name, found " + (name == null ? "nothing" : name));
        }
        if (!Camera.MANUAL.equals(cameraName) && calc.get("SensorWidth") != null) {
            try {
                Camera camera = new Camera(cameraName,
                        PlanJson.toDouble(calc.get("SensorWidth"), where + ".SensorWidth"),
                        PlanJson.toDouble(calc.get("SensorHeight"), where + ".SensorHeight"),
                        PlanJson.integer(calc.get("ImageWidth"), where + ".ImageWidth"),
                        PlanJson.integer(calc.get("ImageHeight"), where + ".ImageHeight"),
                        PlanJson.toDouble(calc.get("FocalLength"), where + ".FocalLength"),
                        PlanJson.toDouble(calc.get("MinTriggerInterval"), where + ".MinTriggerInterval"),
                        PlanJson.bool(calc.get("FixedOrientation"), where + ".FixedOrientation"));
                boolean landscape = PlanJson.bool(calc.get("Landscape"), where + ".Landscape");
                double gsd = PlanJson.toDouble(calc.get("ImageDensity"), where + ".ImageDensity");
                // The footprints before overlap, from the stored GSD as CameraCalc computes them (§1.2).
                double across = (landscape ? camera.imageWidth() : camera.imageHeight()) * gsd / 100;
                double along = (landscape ? camera.imageHeight() : camera.imageWidth()) * gsd / 100;
                return new PhotoGrid(camera, landscape, PlanJson.bool(calc.get("ValueSetIsDistance"), where + ".ValueSetIsDistance"),
                        altitude, gsd, PlanJson.toDouble(calc.get("FrontalOverlap"), where + ".FrontalOverlap"),
                        PlanJson.toDouble(calc.get("SideOverlap"), where + ".SideOverlap"), across, along, spacing, trigger);
            } catch (IllegalArgumentException unusableCamera) {
                if (unusableCamera.getMessage() != null && unusableCamera.getMessage().startsWith(where)) {
                    throw unusableCamera;
                }
            }
        }
        try {
            return PhotoGrid.manual(altitude, spacing, trigger);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(where + ": " + e.getMessage(), e);
        }
    }

    /** The TransectStyleComplexItem's settings; the height reference from its CameraCalc or its v1 FollowTerrain. */
    private static TransectOptions options(Map<?, ?> transect, String where) {
        Map<?, ?> calc = PlanJson.map(transect.get("CameraCalc"), where + ".CameraCalc");
        HeightReference height = height(calc, where + ".CameraCalc");
        Object follow = transect.get("FollowTerrain");
        boolean calcAboveTerrain = follow != null && PlanJson.bool(follow, where + ".FollowTerrain")
                || Integer.valueOf(MODE_CALC_ABOVE_TERRAIN).equals(distanceMode(calc));
        if (calcAboveTerrain) {
            height = HeightReference.ABOVE_TERRAIN;
        }
        boolean refly = PlanJson.bool(transect.get("Refly90Degrees"), where + ".Refly90Degrees");
        return new TransectOptions(PlanJson.toDouble(transect.get("TurnAroundDistance"), where + ".TurnAroundDistance"),
                PlanJson.bool(transect.get("CameraTriggerInTurnAround"), where + ".CameraTriggerInTurnAround"),
                PlanJson.bool(transect.get("HoverAndCapture"), where + ".HoverAndCapture"),
                // QGroundControl turns refly off when it calculates above terrain.
                refly && !calcAboveTerrain, height, Emission.CURRENT);
    }

    private static Integer distanceMode(Map<?, ?> calc) {
        return calc.get("DistanceMode") instanceof Number n ? n.intValue() : null;
    }

    private static HeightReference height(Map<?, ?> calc, String where) {
        Object mode = calc.get("DistanceMode");
        if (mode != null) {
            try {
                return HeightReference.ofQgcDistanceMode(PlanJson.integer(mode, where + ".DistanceMode"));
            } catch (IllegalArgumentException e) {
                throw e.getMessage().startsWith(where) ? e : new IllegalArgumentException(where + ".DistanceMode: " + e.getMessage(), e);
            }
        }
        Object relative = calc.get("DistanceToSurfaceRelative");
        if (relative == null) {
            throw new IllegalArgumentException(where + ": expected DistanceMode (CameraCalc version 2) or"
                    + " DistanceToSurfaceRelative (version 1), found neither");
        }
        return PlanJson.bool(relative, where + ".DistanceToSurfaceRelative") ? HeightReference.ABOVE_HOME
                : HeightReference.ABOVE_SEA_LEVEL;
    }

    /**
     * The ComplexItem QGroundControl saves for a mapping item.
     *
     * @param items its expanded items as the mission has them, numbered from their seq
     */
    static Map<String, Object> write(MappingItem m, List<MissionItem> items) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("type", "ComplexItem");
        json.put("complexItemType", m.qgcType());
        if (m instanceof PolygonSurvey s) {
            json.put("version", SURVEY_VERSION);
            json.put("polygon", latLons(s.polygon()));
            json.put("angle", number(s.angle()));
            json.put("entryLocation", s.entry().ordinal());
            json.put("flyAlternateTransects", s.alternateTransects());
            json.put("splitConcavePolygons", false);
            json.put("TransectStyleComplexItem", transectStyle(m, s.options(), items));
        } else if (m instanceof CorridorScan c) {
            json.put("version", CORRIDOR_VERSION);
            json.put("polyline", latLons(c.polyline()));
            json.put("CorridorWidth", number(c.width()));
            json.put("EntryPoint", c.entry().ordinal());
            json.put("TransectStyleComplexItem", transectStyle(m, c.options(), items));
        } else if (m instanceof StructureScan s) {
            json.put("version", STRUCTURE_VERSION);
            json.put("polygon", latLons(s.polygon()));
            json.put("StructureHeight", number(s.structureHeight()));
            json.put("ScanBottomAlt", number(s.scanBottom()));
            json.put("Layers", s.layers());
            json.put("StartFromTop", s.startFromTop());
            json.put("EntranceAltitude", number(s.entranceAltitude()));
            json.put("GimbalPitch", number(s.gimbalPitch()));
            // A structure scan's waypoints are always above home, whatever the distance mode says.
            json.put("CameraCalc", cameraCalc(s.photoGrid(), HeightReference.ABOVE_HOME));
        }
        return json;
    }

    private static Map<String, Object> transectStyle(MappingItem m, TransectOptions o, List<MissionItem> items) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("version", TRANSECT_STYLE_VERSION);
        json.put("TurnAroundDistance", number(o.turnaround()));
        json.put("CameraTriggerInTurnAround", o.triggerInTurnarounds());
        json.put("HoverAndCapture", o.hoverAndCapture());
        json.put("Refly90Degrees", o.refly90());
        json.put("CameraShots", m.coverage().photos());
        json.put("CameraCalc", cameraCalc(m.photoGrid(), o.height()));
        List<Object> visual = new ArrayList<>();
        for (TransectPoint p : m.path()) {
            visual.add(List.of(number(p.latitude()), number(p.longitude())));
        }
        json.put("VisualTransectPoints", visual);
        List<Object> simple = new ArrayList<>();
        for (MissionItem it : items) {
            simple.add(PlanFile.simpleItem(it, it.seq()));
        }
        json.put("Items", simple);
        return json;
    }

    /** CameraCalc version 2: the Manual camera's three values, or every camera number as QGroundControl saves them. */
    private static Map<String, Object> cameraCalc(PhotoGrid g, HeightReference height) {
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("version", CAMERA_CALC_VERSION);
        Camera c = g.camera();
        // QGroundControl knows a camera by its canonical name; any other is its Custom Camera with the same numbers.
        json.put("CameraName", g.manual() ? Camera.MANUAL : Cameras.named(c.name()).isPresent() ? c.name() : Camera.CUSTOM);
        json.put("DistanceToSurface", number(g.altitude()));
        json.put("DistanceMode", height.qgcDistanceMode());
        json.put("AdjustedFootprintSide", number(g.spacing()));
        json.put("AdjustedFootprintFrontal", number(g.triggerDistance()));
        if (!g.manual()) {
            json.put("ValueSetIsDistance", g.valueSetIsDistance());
            json.put("ImageDensity", number(g.gsd()));
            json.put("FrontalOverlap", number(g.frontOverlap()));
            json.put("SideOverlap", number(g.sideOverlap()));
            json.put("SensorWidth", number(c.sensorWidth()));
            json.put("SensorHeight", number(c.sensorHeight()));
            json.put("ImageWidth", c.imageWidth());
            json.put("ImageHeight", c.imageHeight());
            json.put("FocalLength", number(c.focalLength()));
            json.put("Landscape", g.landscape());
            json.put("FixedOrientation", c.fixedOrientation());
            json.put("MinTriggerInterval", number(c.minTriggerInterval()));
        }
        return json;
    }

    private static List<Object> latLons(List<Position> vertices) {
        List<Object> list = new ArrayList<>();
        for (Position p : vertices) {
            list.add(List.of(number(p.latitudeDegrees()), number(p.longitudeDegrees())));
        }
        return list;
    }

    /** A double as JSON, its shortest decimal that reads back the same (QGroundControl writes doubles). */
    static Object number(double d) {
        return FileValues.jsonDouble(d);
    }
}
