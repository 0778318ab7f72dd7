package dolphin.mission.dsl;

import dolphin.core.Position;
import dolphin.dsl.DslException;
import dolphin.dsl.vocabulary.Word;
import dolphin.mission.model.Fence;
import dolphin.mission.model.FenceRegion;
import dolphin.mission.model.MissionItem;
import groovy.lang.Closure;
import groovy.lang.DelegatesTo;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;

/**
 * The delegate of {@code fence { ... }} inside {@code mission { }} (docs/airspace.md):
 * {@code inclusion polygon(p1, p2, p3, ...)}, {@code exclusion circle(center, radius)},
 * {@code returnPoint p} and {@code enable true}. Regions are horizontal (ArduPilot's are); the
 * return point keeps its height above mean sea level.
 */
public final class FenceBuilder extends ClosureDelegate {

    /** A polygon or circle not yet said to be an inclusion or an exclusion. */
    public record Shape(List<Position> vertices, Position center, double radius) {
        FenceRegion region(boolean inclusion) {
            return vertices != null ? new FenceRegion.Polygon(inclusion, vertices)
                    : new FenceRegion.Circle(inclusion, center, radius);
        }
    }

    private final List<FenceRegion> regions = new ArrayList<>();
    private Position returnPoint;
    private boolean enabled;

    FenceBuilder() {
        super("fence", Set.of("inclusion", "exclusion", "polygon", "circle", "returnPoint", "enable"));
    }

    /** A polygon of at least 3 positions (heights ignored), not closed: the last vertex joins the first. */
    @Word("A polygon of three or more positions, for inclusion or exclusion")
    public Shape polygon(Position... vertices) {
        if (vertices == null || vertices.length < 3) {
            throw new DslException("fence: polygon needs at least 3 positions, got " + (vertices == null ? 0 : vertices.length));
        }
        List<Position> vs = new ArrayList<>();
        for (Position v : vertices) {
            vs.add(Args.position("fence: polygon", v));
        }
        return new Shape(vs, null, 0);
    }

    /** A circle of {@code radius} metres around a position. */
    @Word("A circle: a centre and a radius in metres, for inclusion or exclusion")
    public Shape circle(Position center, Number radius) {
        double r = Args.number("fence: circle", "radius", radius);
        if (!(r > 0)) {
            throw new DslException("fence: circle radius must be above 0 m, got " + radius);
        }
        return new Shape(null, Args.position("fence: circle", center), r);
    }

    /** The vehicle must stay inside. */
    @Word("The vehicle must stay inside this polygon or circle")
    public void inclusion(Shape shape) {
        regions.add(require("inclusion", shape).region(true));
    }

    /** The vehicle must stay outside. */
    @Word("The vehicle must stay outside this polygon or circle")
    public void exclusion(Shape shape) {
        regions.add(require("exclusion", shape).region(false));
    }

    /** Where the vehicle goes on a breach when the fence action is to go there. */
    @Word("Where the vehicle goes on a breach, when the fence action says to")
    public void returnPoint(Position position) {
        returnPoint = Args.position("fence: returnPoint", position);
    }

    /** Switches the fence on when the mission starts (MAV_CMD_DO_FENCE_ENABLE); off by default. */
    @Word("Switches the fence on when the mission starts (off unless said)")
    public void enable(boolean on) {
        enabled = on;
    }

    /** Any other arguments to a fence word: say what it takes. */
    public Object methodMissing(String name, Object args) {
        Object[] argv = args instanceof Object[] a ? a : new Object[] {args};
        String forms = switch (name) {
            case "inclusion", "exclusion" -> name + " polygon(p1, p2, p3, ...) or " + name + " circle(center, radius)";
            case "polygon" -> "polygon(p1, p2, p3, ...): positions";
            case "circle" -> "circle(center, radius)";
            case "returnPoint" -> "returnPoint position";
            case "enable" -> "enable true or enable false";
            default -> null;
        };
        if (forms == null) {
            throw new groovy.lang.MissingMethodException(name, FenceBuilder.class, argv);
        }
        throw new DslException("fence: expected " + forms + ", got " + Arrays.toString(argv));
    }

    boolean enabled() {
        return enabled;
    }

    Fence fence() {
        if (regions.isEmpty()) {
            throw new DslException("fence: no region: expected inclusion polygon(...), exclusion circle(...), ...");
        }
        return Fence.of(regions, returnPoint, MissionItem.GLOBAL_INT);
    }

    private static Shape require(String word, Shape shape) {
        if (shape == null) {
            throw new DslException("fence: " + word + " needs polygon(...) or circle(...), got null");
        }
        return shape;
    }

    /** Runs the block with a new builder as its delegate. */
    static FenceBuilder build(@DelegatesTo(value = FenceBuilder.class, strategy = Closure.DELEGATE_FIRST) Closure<?> body) {
        FenceBuilder b = new FenceBuilder();
        b.run(body);
        return b;
    }
}
