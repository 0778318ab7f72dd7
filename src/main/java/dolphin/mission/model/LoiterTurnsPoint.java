package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;

/**
 * Circle a position a number of times: one MAV_CMD_NAV_LOITER_TURNS (commands 9, 12 and 15
 * of docs/mission-commands.md).
 * p1 = turns (default 10), p2 = 0, p3 = radius (metres, clockwise), p4 = 0 (exit at the centre).
 */
public final class LoiterTurnsPoint extends CirclingPoint {

    public static final int DEFAULT_TURNS = 10;

    private final int turns;

    public LoiterTurnsPoint(String word, Position center, int turns, float radius) {
        super(word, center, MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, turns, radius);
        this.turns = turns;
    }

    public int turns() {
        return turns;
    }

    @Override
    public String toString() {
        return name() + " " + getPosition() + " turns " + turns + " radius " + radius();
    }
}
