package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;

/**
 * Circle a position for a time: one MAV_CMD_NAV_LOITER_TIME (commands 10, 13 and 16 of
 * docs/mission-commands.md).
 * p1 = seconds, p2 = 0, p3 = radius (metres, clockwise), p4 = 0 (exit at the centre).
 */
public final class LoiterTimePoint extends CirclingPoint {

    private final int seconds;

    public LoiterTimePoint(String word, Position center, int seconds, float radius) {
        super(word, center, MAV_CMD.MAV_CMD_NAV_LOITER_TIME, seconds, radius);
        this.seconds = seconds;
    }

    public int seconds() {
        return seconds;
    }

    @Override
    public String toString() {
        return name() + " " + getPosition() + " " + seconds + " s radius " + radius();
    }
}
