package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.core.Position;
import dolphin.mavlink.VehicleState;
import dolphin.mission.model.MissionItem;
import java.time.Duration;
import java.util.Locale;
import java.util.Set;

/**
 * Finds a vehicle that makes no progress toward the item it flies (docs/failures.md, "A stall"): in
 * AUTO, not paused, its distance to the item's place has not come down by {@link #PROGRESS_METRES}
 * for the warning time (one line), then for the limit (the error). The distance is three-dimensional,
 * so a climb, a sub's slow dive or a descent is progress. Items that make the vehicle wait are never a
 * stall: a vehicle at its waypoint (within the item's acceptance radius or the family's) holding for
 * the item's hold time, one circling a loiter item, a NAV_DELAY, any item without a place, and a vehicle
 * whose position has not been heard for 5 s (a sub silent at depth: the link's rules judge it). Fed one
 * snapshot at a time with the clock's time.
 */
final class StallWatch {

    /** What one look found: a warning to report once (a vehicle event, without the vehicle's name), an error, or neither. */
    record Notice(String warning, String error) {
        static final Notice NONE = new Notice(null, null);
    }

    /** How much closer the vehicle must get for it to count as progress: more than a hover's wander. */
    static final double PROGRESS_METRES = 1;
    /** How far above or below its item's height a vehicle at the item's place may be and still count as there. */
    private static final double THERE_HEIGHT_METRES = 3;
    /** A margin on the acceptance radius: a vehicle passes close to its waypoint, not through it. */
    private static final double THERE_MARGIN_METRES = 5;
    private static final Set<Integer> WAYPOINTS = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT);
    private static final Set<Integer> LOITERS = Set.of(MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, MAV_CMD.MAV_CMD_NAV_LOITER_TURNS,
            MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT);
    /** A position older than this is no evidence: a vehicle we do not hear (a sub deep down) is the link's to judge. */
    private static final long FRESH_NANOS = 5_000_000_000L;
    private static final Set<Integer> CLIMBS = Set.of(MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF);

    private final FlightRules rules;
    private final ItemNames names;
    private final String vehicle;
    private final Duration warning;
    private final Duration limit;
    private int item = -1;
    private double best;
    private long since;
    private boolean warned;

    StallWatch(FlightRules rules, ItemNames names, String vehicle, Duration warning, Duration limit) {
        this.rules = rules;
        this.names = names;
        this.vehicle = vehicle;
        this.warning = warning;
        this.limit = limit;
    }

    /**
     * One look at the vehicle.
     *
     * @param current the item under way
     * @param watching whether the vehicle flies its mission itself (in AUTO, not paused): the clock runs only then
     */
    Notice look(VehicleState s, int current, boolean watching, long now) {
        double away = watching && now - s.positionNanos() <= FRESH_NANOS ? distance(s, names.get(current)) : Double.NaN;
        if (current != item || Double.isNaN(away) || away < best - PROGRESS_METRES) {
            item = current;
            best = Double.isNaN(away) ? Double.MAX_VALUE : away;
            since = now;
            warned = false;
            return Notice.NONE;
        }
        long still = now - since;
        String where = String.format(Locale.ROOT, "%.0f m from", away);
        if (still > limit.toNanos()) {
            return new Notice(null, "vehicle " + vehicle + " stalled: no progress toward " + names.item(current) + " for "
                    + limit.toSeconds() + " s, " + where + " it (the stall limit)" + ItemNames.where(s));
        }
        if (still > warning.toNanos() && !warned) {
            warned = true;
            return new Notice("no progress toward " + names.item(current) + ": " + where + " it, no closer for "
                    + warning.toSeconds() + " s", null);
        }
        return Notice.NONE;
    }

    /**
     * How far the vehicle is from where the item takes it, in metres; NaN when the item has no place,
     * when the vehicle is there doing the item's waiting, or when its position is unknown.
     */
    private double distance(VehicleState s, MissionItem i) {
        Position p = s.position();
        boolean climb = CLIMBS.contains(i.command());
        boolean placed = (i.x() != 0 || i.y() != 0) && !climb;
        if (p == null || !placed && !climb || !(WAYPOINTS.contains(i.command()) || LOITERS.contains(i.command()) || climb)) {
            return Double.NaN;
        }
        double vertical = height(s, i);
        double horizontal = placed ? p.horizontalDistanceTo(i.position()) : 0;
        if (placed && waits(i) && horizontal <= thereRadius(i) && (Double.isNaN(vertical) || Math.abs(vertical) <= THERE_HEIGHT_METRES)) {
            return Double.NaN;
        }
        return Math.hypot(horizontal, Double.isNaN(vertical) ? 0 : vertical);
    }

    /** How far the item's height is from the vehicle's, in the item's frame; NaN for heights above terrain. */
    private static double height(VehicleState s, MissionItem i) {
        return switch (MissionItem.altitudeReference(i.frame())) {
            case MAV_FRAME.MAV_FRAME_GLOBAL -> i.z() - s.position().hae();
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT -> i.z() - s.relativeAlt();
            default -> Double.NaN;
        };
    }

    /**
     * Whether the vehicle waits once there: a loiter, or a waypoint with a hold time. At a waypoint
     * without one ArduPilot goes on at once, so a vehicle that hangs near it is stalled too.
     */
    private boolean waits(MissionItem i) {
        return LOITERS.contains(i.command()) || rules.holdsAt(i);
    }

    /** Within this of the item's place, the vehicle is there: at its waypoint, or circling its loiter. */
    private double thereRadius(MissionItem i) {
        double radius = LOITERS.contains(i.command()) ? Math.max(Math.abs(i.param3()), rules.loiterRadius())
                : rules.arrivalRadius(i);
        return radius + THERE_MARGIN_METRES;
    }
}
