package dolphin.mission.dsl;

import dolphin.core.Position;
import dolphin.dsl.DslException;
import dolphin.dsl.vocabulary.Word;
import dolphin.mission.model.Fence;
import dolphin.mission.survey.PhotoGrid;
import dolphin.mission.survey.PolygonSurvey;
import groovy.lang.Closure;
import groovy.lang.DelegatesTo;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The delegate of {@code survey { ... }} (docs/mission-commands.md, "Mapping"): QGroundControl's
 * survey over a polygon, flown in parallel lines at a grid angle.
 */
public final class SurveyBuilder extends TransectBuilder {

    private static final String POLYGON = "The area: three or more positions (not closed), or from a file (file:"
            + " 'field.kml': KML, GeoJSON, .plan, .poly) or the mission's fence (fence: 1)";

    private List<Position> polygon;
    private double angle;
    private boolean fewestPasses;
    private boolean alternate;
    private boolean refly;

    SurveyBuilder(Supplier<Fence> fence) {
        super("survey", Set.of("polygon", "angle", "fewestPasses", "alternateTransects", "reflyCrosswise", "hoverAndCapture"), fence);
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

    @Word("The flight lines' heading, degrees from north (default 0: north-south lines)")
    public void angle(Number degrees) {
        once("angle");
        angle = Args.number(word, "angle", degrees);
    }

    @Word("Picks the grid angle (whole degrees) that needs the fewest lines")
    public void fewestPasses() {
        once("angle");
        fewestPasses = true;
    }

    @Word("Stops at each photo and takes it (multirotors, not planes), instead of triggering by distance on the move")
    public void hoverAndCapture() {
        hover();
    }

    @Word("true: flies every other line, then the ones between on the way back (planes turn wider)")
    public void alternateTransects(boolean on) {
        alternate = on;
    }

    @Word("true: flies the area a second time with lines at 90 degrees to the first")
    public void reflyCrosswise(boolean on) {
        refly = on;
    }

    PolygonSurvey survey() {
        if (polygon == null) {
            throw new DslException("survey: which area? expected 'polygon p1, p2, p3, ...', 'polygon file: PATH' or"
                    + " 'polygon fence: 1'");
        }
        PhotoGrid grid = photoGrid("altitude");
        try {
            double a = fewestPasses ? PolygonSurvey.fewestPassesAngle(polygon, grid.spacing()) : angle;
            return new PolygonSurvey("survey", polygon, grid, a, entryCorner(), alternate, options().withRefly90(refly));
        } catch (IllegalArgumentException e) {
            throw new DslException("survey: " + e.getMessage());
        }
    }

    static PolygonSurvey build(Supplier<Fence> fence,
                               @DelegatesTo(value = SurveyBuilder.class, strategy = Closure.DELEGATE_FIRST) Closure<?> body) {
        SurveyBuilder b = new SurveyBuilder(fence);
        b.run(body);
        return b.survey();
    }
}
