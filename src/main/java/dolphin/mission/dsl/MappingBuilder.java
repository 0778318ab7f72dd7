package dolphin.mission.dsl;

import dolphin.core.Position;
import dolphin.dsl.DslException;
import dolphin.dsl.vocabulary.Word;
import dolphin.mission.file.PolygonFile;
import dolphin.mission.model.Fence;
import dolphin.mission.model.FenceRegion;
import dolphin.mission.survey.Camera;
import dolphin.mission.survey.Cameras;
import dolphin.mission.survey.PhotoGrid;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The words every mapping block has (docs/mission-commands.md, "Mapping"): the camera, named or
 * given by its numbers, or none ("manual": the spacing and trigger distance given in metres); how
 * high, as a height or as a ground resolution; the overlaps. A word's mistake is a script error at
 * its line; what is missing is one at the block's line, when the block ends.
 */
public abstract class MappingBuilder extends ClosureDelegate {

    /** QGroundControl's default overlaps, percent. */
    public static final double DEFAULT_OVERLAP = 70;

    private static final String CAMERA = "The camera: a name QGroundControl knows (camera 'Sony a6000 16mm'), or its numbers:"
            + " sensorWidth:, sensorHeight: (mm), imageWidth:, imageHeight: (px), focalLength: (mm)";

    /** The keys of {@code camera sensorWidth: ..., ...}, in the order messages list them. */
    private static final List<String> CAMERA_KEYS = List.of("sensorWidth", "sensorHeight", "imageWidth", "imageHeight",
            "focalLength", "minTriggerInterval", "name");

    protected final String word;
    private final Supplier<Fence> fence;
    private Camera camera;
    private boolean landscape = true;
    private double altitude = Double.NaN;
    private double gsd = Double.NaN;
    private double frontOverlap = DEFAULT_OVERLAP;
    private double sideOverlap = DEFAULT_OVERLAP;
    private double triggerDistance = Double.NaN;
    private final Set<String> said = new HashSet<>();

    /**
     * @param word the block's word, for messages
     * @param words the block's own words (beyond the camera words), so that one read as a variable says so
     * @param fence the mission's fence so far, for {@code polygon fence: n}
     */
    MappingBuilder(String word, Set<String> words, Supplier<Fence> fence) {
        super(word, union(words, Set.of("camera", "landscape", "altitude", "gsd", "frontOverlap", "sideOverlap",
                "triggerDistance")));
        this.word = word;
        this.fence = fence;
    }

    /** The words of a block and of the blocks it extends, for {@link ClosureDelegate}. */
    static Set<String> union(Set<String> a, Set<String> b) {
        Set<String> all = new HashSet<>(a);
        all.addAll(b);
        return all;
    }

    // ---- the camera

    @Word(CAMERA)
    public void camera(String name) {
        once("camera");
        if (name == null) {
            throw new DslException(word + ": camera: expected a camera's name, got null");
        }
        camera = Cameras.named(name).orElseThrow(() -> new DslException(word + ": camera: no camera named '" + name
                + "'" + nearest(name) + "; name one of 'dolphin cameras', or give its numbers:"
                + " camera sensorWidth: MM, sensorHeight: MM, imageWidth: PX, imageHeight: PX, focalLength: MM"));
    }

    @Word(CAMERA)
    public void camera(Map<String, ?> numbers) {
        once("camera");
        Map<String, Object> given = new LinkedHashMap<>(numbers);
        given.keySet().removeAll(CAMERA_KEYS);
        if (!given.isEmpty()) {
            throw new DslException(word + ": camera: unknown " + given.keySet() + ": expected " + CAMERA_KEYS);
        }
        try {
            camera = new Camera(numbers.containsKey("name") ? String.valueOf(numbers.get("name")) : Camera.CUSTOM,
                    cameraNumber(numbers, "sensorWidth", "mm"), cameraNumber(numbers, "sensorHeight", "mm"),
                    (int) pixels(numbers, "imageWidth"), (int) pixels(numbers, "imageHeight"),
                    cameraNumber(numbers, "focalLength", "mm"),
                    numbers.containsKey("minTriggerInterval") ? cameraNumber(numbers, "minTriggerInterval", "s") : 0, false);
        } catch (IllegalArgumentException e) {
            throw new DslException(word + ": camera: " + e.getMessage());
        }
    }

    private double cameraNumber(Map<String, ?> numbers, String key, String unit) {
        Object v = numbers.get(key);
        if (!(v instanceof Number n)) {
            throw new DslException(word + ": camera: " + key + " must be a number of " + unit + ", got "
                    + (v == null ? "nothing" : Args.show(v)) + " (the camera's numbers: " + CAMERA_KEYS.subList(0, 5) + ")");
        }
        return n.doubleValue();
    }

    private double pixels(Map<String, ?> numbers, String key) {
        double px = cameraNumber(numbers, key, "pixels");
        if (px != Math.rint(px) || px > Integer.MAX_VALUE) {
            throw new DslException(word + ": camera: " + key + " must be a whole number of pixels, got " + Args.show(numbers.get(key)));
        }
        return px;
    }

    private static String nearest(String name) {
        List<String> near = Cameras.closest(name, 3);
        return near.isEmpty() ? "" : " (did you mean '" + String.join("', '", near) + "'?)";
    }

    @Word("true: the image's long side across the flight lines (the default); false: portrait")
    public void landscape(boolean on) {
        landscape = on;
    }

    // ---- how high, how dense

    @Word("How high the camera flies, metres above home (see heightAbove)")
    public void altitude(Number metres) {
        distance("altitude", metres);
    }

    /** The camera's distance from what it photographs, under the block's own word for it. */
    final void distance(String name, Number metres) {
        once(name);
        altitude = Args.positive(word, name, metres);
    }

    @Word("The ground resolution, centimetres per pixel: sets the altitude from the camera")
    public void gsd(Number centimetresPerPixel) {
        once("gsd");
        gsd = Args.positive(word, "ground resolution (cm/px)", centimetresPerPixel);
    }

    @Word("How much each photo overlaps the next along a line, percent (default 70)")
    public void frontOverlap(Number percent) {
        frontOverlap = overlap("frontOverlap", percent);
    }

    @Word("How much neighbouring lines' photos overlap, percent (default 70)")
    public void sideOverlap(Number percent) {
        sideOverlap = overlap("sideOverlap", percent);
    }

    private double overlap(String name, Number percent) {
        double p = Args.number(word, name, percent);
        if (!(p > 0 && p < 100)) {
            throw new DslException(word + ": " + name + " must be above 0 and below 100 %, got " + Args.show(percent)
                    + (p >= 100 ? ": photos that overlap entirely never move on" : ": photos that only touch leave gaps"
                    + " wherever the vehicle drifts"));
        }
        return p;
    }

    @Word("Without a camera: metres between photos (0: none, the default)")
    public void triggerDistance(Number metres) {
        once("triggerDistance");
        triggerDistance = Args.notNegative(word, "trigger distance", metres);
    }

    // ---- outlines

    /** The vertices of a polygon or path given as positions, at least {@code min} of them. */
    final List<Position> vertices(String what, Position[] given, int min) {
        List<Position> out = new ArrayList<>();
        for (Position p : given == null ? new Position[0] : given) {
            out.add(Args.position(word + ": " + what, p));
        }
        return atLeast(what, out, min);
    }

    /**
     * An outline from a file ({@code file: 'field.kml'}: KML, GeoJSON, a QGroundControl plan, a .poly)
     * or, for a polygon, from the mission's fence ({@code fence: 1}: its first inclusion polygon).
     */
    final List<Position> verticesFrom(String what, Map<String, ?> from, int min, boolean polygon) {
        if (from.size() != 1 || !(from.containsKey("file") || polygon && from.containsKey("fence"))) {
            throw new DslException(word + ": " + what + ": expected " + what + " p1, p2, ... (positions), " + what
                    + " file: 'PATH'" + (polygon ? " or polygon fence: N (the mission's Nth inclusion polygon)" : "")
                    + ", got " + from);
        }
        if (from.containsKey("fence")) {
            return atLeast(what, fencePolygon(from.get("fence")), min);
        }
        Path file = Path.of(String.valueOf(from.get("file")));
        if (!Files.isRegularFile(file)) {
            throw new DslException(word + ": " + what + ": no file " + file + " (paths are relative to "
                    + Path.of("").toAbsolutePath() + ")");
        }
        try {
            return atLeast(what, polygon ? PolygonFile.readPolygon(file) : PolygonFile.readPolyline(file), min);
        } catch (IOException e) {
            throw new DslException(word + ": " + what + ": cannot read " + file + ": " + e.getMessage());
        } catch (IllegalArgumentException e) {
            throw new DslException(word + ": " + what + ": " + e.getMessage());
        }
    }

    private List<Position> fencePolygon(Object which) {
        if (!(which instanceof Number n) || n.doubleValue() != Math.rint(n.doubleValue()) || n.intValue() < 1) {
            throw new DslException(word + ": polygon fence: expected the number of an inclusion polygon, 1 for the first, got "
                    + Args.show(which));
        }
        List<FenceRegion.Polygon> inclusions = new ArrayList<>();
        for (FenceRegion r : fence.get().regions()) {
            if (r instanceof FenceRegion.Polygon p && p.inclusion()) {
                inclusions.add(p);
            }
        }
        if (n.intValue() > inclusions.size()) {
            throw new DslException(word + ": polygon fence: " + n.intValue() + ": the mission's fence has "
                    + (inclusions.isEmpty() ? "no inclusion polygon (write the fence { } block before the survey)"
                    : inclusions.size() + " inclusion polygon" + (inclusions.size() == 1 ? "" : "s")));
        }
        return inclusions.get(n.intValue() - 1).vertices();
    }

    private List<Position> atLeast(String what, List<Position> vertices, int min) {
        if (vertices.size() < min) {
            throw new DslException(word + ": a " + what + " needs at least " + min + " vertices, got " + vertices.size());
        }
        return vertices;
    }

    // ---- building

    /** Says a word may be given once: a second one is a mistake, not an override. */
    final void once(String name) {
        if (!said.add(name)) {
            throw new DslException(word + ": " + name + " is given twice; a " + word + " has one");
        }
    }

    final boolean said(String name) {
        return said.contains(name);
    }

    /** Without a camera: metres between photos, 0 when not said. */
    final double manualTriggerDistance() {
        return Double.isNaN(triggerDistance) ? 0 : triggerDistance;
    }

    /**
     * The photo grid the words describe: from the camera and the altitude or resolution, or without a
     * camera from the block's distances ({@link #manualGrid}).
     *
     * @param altitudeWord the block's word for how far the camera is from what it sees
     */
    final PhotoGrid photoGrid(String altitudeWord) {
        try {
            if (camera == null) {
                if (said("gsd")) {
                    throw new DslException(word + ": gsd needs a camera: say which ('camera NAME' or its numbers), or"
                            + " give the distances in metres: " + manualWords(altitudeWord));
                }
                if (Double.isNaN(altitude)) {
                    throw new DslException(word + ": say how to take the photos: a camera ('camera NAME' and '"
                            + altitudeWord + " METRES' or 'gsd CM_PER_PX'), or without one " + manualWords(altitudeWord));
                }
                return manualGrid(altitude);
            }
            if (manualWordsSaid()) {
                throw new DslException(word + ": with a camera, the distances between lines and photos come from its"
                        + " footprint and the overlaps; give a camera or " + manualWords(altitudeWord) + ", not both");
            }
            if (Double.isNaN(altitude) == Double.isNaN(gsd)) {
                throw new DslException(word + ": with a camera, give either '" + altitudeWord + " METRES' or 'gsd CM_PER_PX'"
                        + (Double.isNaN(altitude) ? "" : ", not both"));
            }
            return Double.isNaN(gsd) ? PhotoGrid.atAltitude(camera, landscape, altitude, frontOverlap, sideOverlap)
                    : PhotoGrid.atGsd(camera, landscape, gsd, frontOverlap, sideOverlap);
        } catch (IllegalArgumentException e) {
            throw new DslException(word + ": " + e.getMessage());
        }
    }

    /** The words that replace a camera in this block, for messages, e.g. "'altitude M', 'spacing M' and 'triggerDistance M'". */
    abstract String manualWords(String altitudeWord);

    /** Whether a word that replaces a camera was said. */
    abstract boolean manualWordsSaid();

    /** Without a camera: the grid from the block's own distances, at the given distance from the ground or walls. */
    abstract PhotoGrid manualGrid(double altitude);
}
