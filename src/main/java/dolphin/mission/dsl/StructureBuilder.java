package dolphin.mission.dsl;

import dolphin.core.Position;
import dolphin.dsl.DslException;
import dolphin.dsl.vocabulary.Word;
import dolphin.mission.model.Fence;
import dolphin.mission.survey.PhotoGrid;
import dolphin.mission.survey.StructureScan;
import groovy.lang.Closure;
import groovy.lang.DelegatesTo;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The delegate of {@code structureScan { ... }} (docs/mission-commands.md, "Mapping"): rings around a
 * building's footprint at a distance, one a layer, photographing its walls. Heights are metres
 * above home, as QGroundControl flies them.
 */
public final class StructureBuilder extends MappingBuilder {

    private static final String POLYGON = "The structure's footprint: three or more positions (not closed), or from a"
            + " file (file: 'building.kml': KML, GeoJSON, .plan, .poly) or the mission's fence (fence: 1)";

    private List<Position> polygon;
    private double structureHeight = Double.NaN;
    private double bottom;
    private double entrance = Double.NaN;
    private boolean fromTop = true;
    private double layerHeight = Double.NaN;

    StructureBuilder(Supplier<Fence> fence) {
        super("structureScan", Set.of("polygon", "height", "bottom", "distance", "layerHeight", "startFromTop",
                "entranceAltitude"), fence);
    }

    @Word(POLYGON)
    public void polygon(Position... vertices) {
        once("polygon");
        polygon = vertices("polygon", vertices, 3);
    }

    @Word(POLYGON)
    public void polygon(Map<String, ?> from) {
        once("polygon");
        polygon = verticesFrom("polygon", from, 3, true);
    }

    @Word("The structure's height, metres above home: the top of the scan")
    public void height(Number metres) {
        once("height");
        structureHeight = Args.positive(word, "structure height", metres);
    }

    @Word("The lowest height scanned, metres above home (default 0)")
    public void bottom(Number metres) {
        once("bottom");
        bottom = Args.notNegative(word, "bottom of the scan", metres);
    }

    @Word("How far from the walls the vehicle flies, metres")
    public void distance(Number metres) {
        distance("distance", metres);
    }

    @Override
    public void altitude(Number metres) {
        throw new DslException(word + ": a structure scan flies at a distance from the walls, layer by layer: 'distance"
                + " METRES', and 'height' and 'bottom' for what it covers");
    }

    @Word("Without a camera: metres between layers")
    public void layerHeight(Number metres) {
        once("layerHeight");
        layerHeight = Args.positive(word, "layer height", metres);
    }

    @Word("true (the default): the first layer is the top one")
    public void startFromTop(boolean on) {
        fromTop = on;
    }

    @Word("The height the scan is entered and left at, metres above home (default: the structure's height)")
    public void entranceAltitude(Number metres) {
        once("entranceAltitude");
        entrance = Args.positive(word, "entrance altitude", metres);
    }

    @Override
    String manualWords(String altitudeWord) {
        return "'distance METRES', 'layerHeight METRES' and 'triggerDistance METRES' (photos along a ring)";
    }

    @Override
    boolean manualWordsSaid() {
        return said("layerHeight") || said("triggerDistance");
    }

    /**
     * QGroundControl's structure scan reads a grid's frontal distance as the layer height and its side
     * distance as the photo distance along a ring (docs/qgc-surveys.md, §3.2).
     */
    @Override
    PhotoGrid manualGrid(double distance) {
        if (Double.isNaN(layerHeight)) {
            throw new DslException("structureScan: without a camera, say how far apart the layers are: 'layerHeight METRES'");
        }
        return PhotoGrid.manual(distance, manualTriggerDistance(), layerHeight);
    }

    StructureScan structure() {
        if (polygon == null) {
            throw new DslException("structureScan: around what? expected 'polygon p1, p2, p3, ...' or 'polygon file: PATH'");
        }
        if (Double.isNaN(structureHeight)) {
            throw new DslException("structureScan: how tall is the structure? expected 'height METRES' (above home)");
        }
        PhotoGrid grid = photoGrid("distance");
        try {
            return new StructureScan("structureScan", polygon, grid, structureHeight, bottom,
                    Double.isNaN(entrance) ? structureHeight : entrance, fromTop, 0);
        } catch (IllegalArgumentException e) {
            throw new DslException("structureScan: " + e.getMessage());
        }
    }

    static StructureScan build(Supplier<Fence> fence,
                               @DelegatesTo(value = StructureBuilder.class, strategy = Closure.DELEGATE_FIRST) Closure<?> body) {
        StructureBuilder b = new StructureBuilder(fence);
        b.run(body);
        return b.structure();
    }
}
