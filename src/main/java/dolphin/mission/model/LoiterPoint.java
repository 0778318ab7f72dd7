package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;

/**
 * Circle a position until the mission is cut short: one MAV_CMD_NAV_LOITER_UNLIM (commands 8, 11,
 * 14 and 19 of docs/mission-commands.md). p1 = p2 = 0, p3 = radius (metres, clockwise), p4 = 0.
 */
public final class LoiterPoint extends CirclingPoint {

    /** The loiter radius the original builder uses when none is given, in metres. */
    public static final float DEFAULT_RADIUS = 15f;

    public LoiterPoint(String word, Position center, float radius) {
        super(word, center, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, 0, radius);
    }

    @Override
    public String toString() {
        return name() + " " + getPosition() + " radius " + radius();
    }
}
