package dolphin.mission.dsl;

import dolphin.core.Position;
import dolphin.dsl.DslException;
import dolphin.dsl.vocabulary.Word;
import dolphin.mission.model.Fence;
import dolphin.mission.survey.CorridorScan;
import dolphin.mission.survey.PhotoGrid;
import groovy.lang.Closure;
import groovy.lang.DelegatesTo;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The delegate of {@code corridorScan { ... }} (docs/mission-commands.md, "Mapping"): lines along a
 * path (a road, a river, a power line), as many as cover its width.
 */
public final class CorridorBuilder extends TransectBuilder {

    private static final String PATH = "The corridor's centre line: two or more positions, or from a file (file:"
            + " 'road.kml': KML, GeoJSON, .plan, .poly)";

    private List<Position> path;
    private double width = Double.NaN;

    CorridorBuilder(Supplier<Fence> fence) {
        super("corridorScan", Set.of("path", "width"), fence);
    }

    @Word(PATH)
    public void path(Position... vertices) {
        once("path");
        path = vertices("path", vertices, 2);
    }

    @Word(PATH)
    public void path(Map<String, ?> from) {
        once("path");
        path = verticesFrom("path", from, 2, false);
    }

    @Word("The corridor's width, metres, centred on the path")
    public void width(Number metres) {
        once("width");
        width = Args.notNegative(word, "width", metres);
    }

    CorridorScan corridor() {
        if (path == null) {
            throw new DslException("corridorScan: along what? expected 'path p1, p2, ...' or 'path file: PATH'");
        }
        if (Double.isNaN(width)) {
            throw new DslException("corridorScan: how wide? expected 'width METRES'");
        }
        PhotoGrid grid = photoGrid("altitude");
        try {
            return new CorridorScan("corridorScan", path, width, grid, entryCorner(), options());
        } catch (IllegalArgumentException e) {
            throw new DslException("corridorScan: " + e.getMessage());
        }
    }

    static CorridorScan build(Supplier<Fence> fence,
                              @DelegatesTo(value = CorridorBuilder.class, strategy = Closure.DELEGATE_FIRST) Closure<?> body) {
        CorridorBuilder b = new CorridorBuilder(fence);
        b.run(body);
        return b.corridor();
    }
}
