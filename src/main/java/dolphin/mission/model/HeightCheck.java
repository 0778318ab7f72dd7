package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.core.Position;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;

/**
 * A mission never flies lower than home plus a clearance unless its script says so
 * (docs/mission-commands.md, "Safe heights"): every item that flies at its own height (waypoints,
 * loiters, take-offs) must be at least {@link #CLEARANCE} metres above home. Landings are exempt:
 * going down is what they are for. Items above terrain are not checked (the terrain is not known
 * here).
 */
public final class HeightCheck {

    /** Metres above home that flying items keep at least. */
    public static final double CLEARANCE = 2;

    /** Navigation commands flown at the item's own height. */
    private static final Set<Integer> FLOWN_AT_HEIGHT = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM,
            MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_TAKEOFF,
            MAV_CMD.MAV_CMD_NAV_CONTINUE_AND_CHANGE_ALT, MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT,
            MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF);

    /** An item too low: the point that made it, its seq, and the message for the user. */
    public record TooLow(MissionPoint point, int seq, String message) {
    }

    private HeightCheck() {
    }

    /** The first item below home + clearance, or empty (also when home is unknown or the mission allows it). */
    public static Optional<TooLow> firstTooLow(Mission mission, Position home) {
        if (home == null || mission.belowHomeAllowed()) {
            return Optional.empty();
        }
        int seq = 1;
        for (DroneCommand c : mission.getCommandList()) {
            if (!(c instanceof MissionPoint p)) {
                continue;
            }
            for (MissionItem item : p.items(seq)) {
                double height = heightAboveHome(item, home);
                if (FLOWN_AT_HEIGHT.contains(item.command()) && height < CLEARANCE) {
                    return Optional.of(new TooLow(p, item.seq(), String.format(Locale.ROOT,
                            "mission %s: item %d (%s, %s) is %.1f m above home (home at %.1f m): lower than the %.0f m"
                                    + " clearance, into the ground or nearly; only landings go lower. Raise it, or write"
                                    + " 'allowBelowHome true' in the mission if this is intended",
                            mission.getId(), item.seq(), p.name(), item.commandName(), height, home.hae(), CLEARANCE)));
                }
            }
            seq += p.messageCount();
        }
        return Optional.empty();
    }

    /** The item's height above home, from its frame; +infinity for frames whose height is not known here. */
    private static double heightAboveHome(MissionItem item, Position home) {
        return switch (MissionItem.altitudeReference(item.frame())) {
            case MAV_FRAME.MAV_FRAME_GLOBAL -> item.z() - home.hae();
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT -> item.z();
            default -> Double.POSITIVE_INFINITY;
        };
    }
}
