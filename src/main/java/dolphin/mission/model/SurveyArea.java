package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;

/**
 * {@code surveyArea}: a lawn-mower pattern of MAV_CMD_NAV_WAYPOINTs over a {@code length} x
 * {@code width} area from a base position: the original's pattern, made self-consistent
 * (docs/decisions.md, "Missions"):
 *
 * <ul>
 *   <li>N = round(width / spacing) + 1 passes (Java {@link Math#round}, half up);</li>
 *   <li>each pass is a leg of length + 25 m (the original's overshoot) along north or south,
 *       alternating, the first one north for NORTH_* and south for SOUTH_*;</li>
 *   <li>after every pass but the last, a shift of {@code spacing} metres east (*_EAST) or west (*_WEST);</li>
 *   <li>then a waypoint back at the base.</li>
 * </ul>
 *
 * <p>That is 2N items, numbered consecutively, and {@link #messageCount()} is 2N too (the original
 * emitted about half the passes with duplicate seqs, and declared fewer items than it emitted).
 * Every waypoint is at the base's height, with p1 = 0, p2 = 25 m acceptance radius, p3 = 0,
 * p4 = NaN. Horizontal steps use the original's WGS-84 displacement ({@code Wgs84}), each from the
 * previous waypoint.
 */
public final class SurveyArea extends MissionPoint {

    public static final double OVERSHOOT = 25;
    public static final float ACCEPTANCE_RADIUS = 25f;
    public static final double DEFAULT_SPACING = 50;
    public static final SurveyDirection DEFAULT_DIRECTION = SurveyDirection.NORTH_WEST;
    /** The most passes a survey may have: 2N items must fit a MAVLink mission (seq is 16 bits), with home. */
    public static final int MAX_PASSES = 32767;

    private final double length;
    private final double width;
    private final double spacing;
    private final SurveyDirection direction;
    private final List<Position> waypoints;

    /**
     * @param base where the survey starts and ends
     * @param length the length of each pass, without the overshoot, metres (>= 0)
     * @param width the width to cover, metres (>= 0)
     * @param spacing the distance between passes, metres (> 0)
     */
    public SurveyArea(Position base, double length, double width, double spacing, SurveyDirection direction) {
        super("surveyArea", Objects.requireNonNull(base, "base"));
        this.direction = Objects.requireNonNull(direction, "direction");
        if (!(length >= 0) || Double.isInfinite(length)) {
            throw new IllegalArgumentException("the length must be a number of metres, not negative, got " + length);
        }
        if (!(width >= 0) || Double.isInfinite(width)) {
            throw new IllegalArgumentException("the width must be a number of metres, not negative, got " + width);
        }
        if (!(spacing > 0) || Double.isInfinite(spacing)) {
            throw new IllegalArgumentException("the spacing must be a positive number of metres, got " + spacing);
        }
        if (!(width / spacing < MAX_PASSES) || passes(width, spacing) > MAX_PASSES) {
            throw new IllegalArgumentException("a width of " + width + " m with passes " + spacing + " m apart makes "
                    + "more than " + MAX_PASSES + " passes (2 items each); a MAVLink mission holds at most 65535 items");
        }
        long passes = passes(width, spacing);
        this.length = length;
        this.width = width;
        this.spacing = spacing;
        this.waypoints = Collections.unmodifiableList(pattern(base, length, (int) passes, spacing, direction));
    }

    /** N = round(width / spacing) + 1. */
    public static long passes(double width, double spacing) {
        return Math.round(width / spacing) + 1;
    }

    private static List<Position> pattern(Position base, double length, int passes, double spacing, SurveyDirection d) {
        List<Position> out = new ArrayList<>(2 * passes);
        double leg = (length + OVERSHOOT) * d.northSign();
        Position cur = base;
        int along = 1;
        for (int i = 0; i < passes; i++) {
            cur = atHeight(cur.displace(leg * along, 0, 0), base.hae());
            out.add(cur);
            if (i < passes - 1) {
                cur = atHeight(cur.displace(0, spacing * d.eastSign(), 0), base.hae());
                out.add(cur);
                along = -along;
            }
        }
        out.add(base);
        return out;
    }

    /** The horizontal position of p at the given height (no drift from the tangent-plane steps). */
    private static Position atHeight(Position p, double hae) {
        return p.atHeight(hae);
    }

    public double length() {
        return length;
    }

    public double width() {
        return width;
    }

    public double spacing() {
        return spacing;
    }

    public SurveyDirection direction() {
        return direction;
    }

    /** The number of passes, N. */
    public int passes() {
        return (int) passes(width, spacing);
    }

    /** The waypoints in flight order: leg, shift, leg, ..., leg, base. */
    public List<Position> waypoints() {
        return waypoints;
    }

    @Override
    public List<MissionItem> items(int seq) {
        List<MissionItem> items = new ArrayList<>(waypoints.size());
        for (Position p : waypoints) {
            items.add(MissionItem.at(seq++, MAV_CMD.MAV_CMD_NAV_WAYPOINT, p, 0, ACCEPTANCE_RADIUS, 0, Float.NaN));
        }
        return items;
    }

    @Override
    public int messageCount() {
        return waypoints.size();
    }

    @Override
    public String toString() {
        return "surveyArea from " + getPosition() + " " + length + " x " + width + " m, passes " + spacing + " m apart, "
                + direction;
    }
}
