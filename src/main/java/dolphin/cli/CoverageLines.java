package dolphin.cli;

import com.MAVLink.enums.MAV_TYPE;
import dolphin.mission.model.ChangeSpeed;
import dolphin.mission.model.ItemText;
import dolphin.mission.model.Mission;
import dolphin.mission.survey.Coverage;
import dolphin.mission.survey.MappingItem;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * What each mapping item of a mission covers, one line each, for {@code dolphin mission}: the ground
 * resolution, the photos, the flight's length and how long it takes at the mission's speed (the last
 * {@code speed} before it, else the plan's speed for the vehicle, as QGroundControl estimates it).
 */
final class CoverageLines {

    /** The MAV_TYPEs QGroundControl plans at its hover speed. */
    private static final Set<Integer> HOVERING = Set.of(MAV_TYPE.MAV_TYPE_QUADROTOR, MAV_TYPE.MAV_TYPE_HEXAROTOR,
            MAV_TYPE.MAV_TYPE_OCTOROTOR, MAV_TYPE.MAV_TYPE_TRICOPTER, MAV_TYPE.MAV_TYPE_COAXIAL,
            MAV_TYPE.MAV_TYPE_HELICOPTER, MAV_TYPE.MAV_TYPE_DODECAROTOR, MAV_TYPE.MAV_TYPE_DECAROTOR);

    private CoverageLines() {
    }

    static List<String> of(Mission m) {
        List<String> lines = new ArrayList<>();
        double speed = Double.NaN;
        for (Mission.NumberedPoint n : m.numberedPoints()) {
            if (n.point() instanceof ChangeSpeed s) {
                speed = s.speed();
            }
            if (n.point() instanceof MappingItem item) {
                boolean given = !Double.isNaN(speed);
                double v = given ? speed : planSpeed(m);
                lines.add(line(item, n.firstSeq(), n.firstSeq() + item.messageCount() - 1, v, given));
            }
        }
        return lines;
    }

    private static double planSpeed(Mission m) {
        return HOVERING.contains(m.vehicleProfile().vehicleType()) ? m.vehicleProfile().hoverSpeed()
                : m.vehicleProfile().cruiseSpeed();
    }

    private static String line(MappingItem item, int first, int last, double speed, boolean given) {
        Coverage c = item.coverage();
        String gsd = Double.isNaN(c.gsd()) ? "no camera given" : String.format(Locale.ROOT, "GSD %.2f cm/px", c.gsd());
        long seconds = Math.round(c.pathLength() / speed);
        return String.format(Locale.ROOT, "%s (items %d to %d): %s, %d photo%s, %s of flight, %s at %s m/s%s",
                item.name(), first, last, gsd, c.photos(), c.photos() == 1 ? "" : "s", length(c.pathLength()),
                duration(seconds), ItemText.number((float) speed), given ? "" : " (the plan's speed: the mission sets none)");
    }

    private static String length(double metres) {
        return metres >= 1000 ? String.format(Locale.ROOT, "%.2f km", metres / 1000) : String.format(Locale.ROOT, "%.0f m", metres);
    }

    private static String duration(long seconds) {
        long h = seconds / 3600;
        long min = seconds % 3600 / 60;
        long s = seconds % 60;
        return h > 0 ? String.format(Locale.ROOT, "%d h %02d min", h, min) : String.format(Locale.ROOT, "%d min %02d s", min, s);
    }
}
