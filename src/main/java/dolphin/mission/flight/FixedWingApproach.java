package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;

/**
 * PX4's check of a fixed-wing landing's approach (FeasibilityChecker::checkFixedWindLandApproach),
 * made before the upload so that the script hears which item fails and what would do, where PX4
 * would only find the mission infeasible after it: a NAV_LAND straight after an item with a position
 * is entered from a waypoint, or from a loiter to altitude whose circle it lies outside, above the
 * landing, on a glide slope no steeper than FW_LND_ANG. A landing after a command without a position
 * PX4 does not check; heights from different references are left to PX4, which knows its home.
 */
final class FixedWingApproach {

    /** The steepest glide slope the vehicle lands on, degrees. */
    static final String LANDING_ANGLE = "FW_LND_ANG";
    /** FW_LND_ANG's default. */
    static final double DEFAULT_ANGLE = 5;

    /** What PX4 counts as an item with a position (MissionBlock::item_contains_position). */
    private static final Set<Integer> WITH_POSITION = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM,
            MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_LAND, MAV_CMD.MAV_CMD_NAV_TAKEOFF,
            MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, MAV_CMD.MAV_CMD_NAV_VTOL_LAND);

    private FixedWingApproach() {
    }

    /** Why PX4 would refuse the approach to a landing among these items (home first), or empty. */
    static Optional<String> refusal(List<MissionItem> items, double landingAngle) {
        for (int i = 2; i < items.size(); i++) {
            MissionItem land = items.get(i);
            MissionItem entrance = items.get(i - 1);
            if (land.command() == MAV_CMD.MAV_CMD_NAV_LAND && WITH_POSITION.contains(entrance.command())) {
                Optional<String> why = refusal(entrance, land, landingAngle);
                if (why.isPresent()) {
                    return Optional.of("PX4 refuses the approach to the landing at item " + land.seq() + " from item "
                            + entrance.seq() + " (" + entrance.commandName() + "): " + why.get());
                }
            }
        }
        return Optional.empty();
    }

    private static Optional<String> refusal(MissionItem entrance, MissionItem land, double landingAngle) {
        if (MissionItem.altitudeReference(entrance.frame()) != MissionItem.altitudeReference(land.frame())) {
            return Optional.empty();
        }
        double drop = entrance.z() - land.z();
        if (drop <= 0) {
            return Optional.of("it must start above the landing, and starts " + metres(-drop) + " below it");
        }
        double distance = entrance.position().horizontalDistanceTo(land.position());
        double length;
        if (entrance.command() == MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT) {
            double radius = Math.abs(entrance.param2());
            if (distance <= radius) {
                return Optional.of("the landing is " + metres(distance) + " from the loiter's centre, inside its "
                        + metres(radius) + " circle: land outside it");
            }
            length = Math.sqrt(distance * distance - radius * radius);
        } else if (entrance.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT) {
            length = distance;
        } else {
            return Optional.of("a fixed-wing landing is entered from a waypoint or a loiter to altitude");
        }
        // PX4 allows 0.1 degree over its setting, for rounding
        double steepest = Math.tan(Math.toRadians(landingAngle + 0.1));
        if (drop / Math.max(length, 1e-3) <= steepest) {
            return Optional.empty();
        }
        return Optional.of(String.format(Locale.ROOT, "it comes down %s over %s, a glide slope of %.1f degrees, steeper than"
                        + " the vehicle's %.1f (%s): start it at least %s out, or at most %s above the landing",
                metres(drop), metres(length), Math.toDegrees(Math.atan2(drop, length)), landingAngle, LANDING_ANGLE,
                metres(Math.ceil(drop / steepest)), metres(Math.floor(steepest * length))));
    }

    private static String metres(double m) {
        return String.format(Locale.ROOT, "%.0f m", m);
    }
}
