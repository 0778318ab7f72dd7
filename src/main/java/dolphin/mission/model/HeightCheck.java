package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.core.Position;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.function.BiFunction;

/**
 * A mission never goes where its vehicle does not belong unless its script says so
 * (docs/mission-commands.md, "Safe heights"):
 * <ul>
 * <li>In the air, every item that flies at its own height (waypoints, loiters, take-offs) must be at
 *     least {@link #CLEARANCE} metres above home, unless the mission says {@code allowBelowHome}.
 *     Landings are exempt: going down is what they are for.</li>
 * <li>Under water ({@link Mission#underwater()}, docs/underwater.md), every such item and every
 *     surfacing (NAV_LAND) must lie between the surface and the mission's {@code maxDepth}: never
 *     above the water, never deeper than the script allows.</li>
 * </ul>
 * Items above terrain are not checked (the terrain is not known here).
 */
public final class HeightCheck {

    /** Metres above home that flying items keep at least. */
    public static final double CLEARANCE = 2;

    /** How far above the surface an underwater item may be: rounding, not flight. */
    private static final double SURFACE_TOLERANCE = 0.01;

    /** Navigation commands flown at the item's own height. */
    private static final Set<Integer> FLOWN_AT_HEIGHT = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM,
            MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_TAKEOFF,
            MAV_CMD.MAV_CMD_NAV_CONTINUE_AND_CHANGE_ALT, MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT,
            MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF);

    /** An item where its vehicle does not belong: the point that made it, its seq, and the message for the user. */
    public record Unsafe(MissionPoint point, int seq, String message) {
    }

    private HeightCheck() {
    }

    /**
     * The first item out of bounds: under water, above the surface or deeper than the limit; in
     * the air, below home + clearance. Empty when there is none, and for a mission in the air that
     * allows going lower. With home unknown, only items whose height is above home are checked.
     */
    public static Optional<Unsafe> firstUnsafe(Mission mission, Position home) {
        Optional<Underwater> water = mission.underwater();
        if (water.isPresent()) {
            return firstOutOfWater(mission, water.get());
        }
        if (mission.belowHomeAllowed()) {
            return Optional.empty();
        }
        return first(mission, (p, item) -> {
            double height = heightAboveHome(item, home);
            return FLOWN_AT_HEIGHT.contains(item.command()) && height < CLEARANCE ? String.format(Locale.ROOT,
                    "mission %s: item %d (%s, %s) is %.1f m above home%s: lower than the %.0f m"
                            + " clearance, into the ground or nearly; only landings go lower. Raise it, or write"
                            + " 'allowBelowHome true' in the mission if this is intended",
                    mission.getId(), item.seq(), p.name(), item.commandName(), height,
                    home == null ? "" : String.format(Locale.ROOT, " (home at %.1f m)", home.hae()), CLEARANCE) : null;
        });
    }

    private static Optional<Unsafe> firstOutOfWater(Mission mission, Underwater water) {
        return first(mission, (p, item) -> {
            if (!FLOWN_AT_HEIGHT.contains(item.command()) && item.command() != MAV_CMD.MAV_CMD_NAV_LAND) {
                return null;
            }
            double depth = switch (MissionItem.altitudeReference(item.frame())) {
                case MAV_FRAME.MAV_FRAME_GLOBAL -> water.depthOf(item.z());
                // ArduSub's home is at the surface: a height above it is minus a depth
                case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT -> -item.z();
                default -> Double.NaN;
            };
            if (Double.isNaN(depth)) {
                return null;
            }
            String what = String.format(Locale.ROOT, "mission %s: item %d (%s, %s)", mission.getId(), item.seq(), p.name(),
                    item.commandName());
            if (depth < -SURFACE_TOLERANCE) {
                return String.format(Locale.ROOT, "%s is %.1f m above the surface (the surface at %.1f m): out of the water;"
                        + " an underwater mission stays at or below the surface", what, -depth, water.surface());
            }
            if (depth > water.maxDepth()) {
                return String.format(Locale.ROOT, "%s is %.1f m deep: deeper than the mission's limit, maxDepth %s m."
                        + " Raise it, or lower the limit if this is intended", what, depth, number(water.maxDepth()));
            }
            return null;
        });
    }

    private static String number(double d) {
        return d == Math.rint(d) ? String.valueOf((long) d) : String.valueOf(d);
    }

    /** The first item the rule has something to say about. */
    private static Optional<Unsafe> first(Mission mission, BiFunction<MissionPoint, MissionItem, String> rule) {
        for (Mission.NumberedPoint n : mission.numberedPoints()) {
            for (MissionItem item : n.point().items(n.firstSeq())) {
                String problem = rule.apply(n.point(), item);
                if (problem != null) {
                    return Optional.of(new Unsafe(n.point(), item.seq(), problem));
                }
            }
        }
        return Optional.empty();
    }

    /** The item's height above home, from its frame; +infinity for heights not known here (home may be null). */
    private static double heightAboveHome(MissionItem item, Position home) {
        return switch (MissionItem.altitudeReference(item.frame())) {
            case MAV_FRAME.MAV_FRAME_GLOBAL -> home == null ? Double.POSITIVE_INFINITY : item.z() - home.hae();
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT -> item.z();
            default -> Double.POSITIVE_INFINITY;
        };
    }
}
