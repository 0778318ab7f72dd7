package dolphin.mavlink.mission;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.List;
import java.util.Objects;

/**
 * Circle a position a number of times: one MAV_CMD_NAV_LOITER_TURNS (reference C.6 rows 9, 12, 15).
 * p1 = turns (default 10), p2 = 0, p3 = radius (metres, clockwise), p4 = 0 (exit at the centre).
 */
public final class LoiterTurnsPoint extends MissionPoint {

    public static final int DEFAULT_TURNS = 10;

    private final String word;
    private final int turns;
    private final float radius;

    public LoiterTurnsPoint(String word, Position center, int turns, float radius) {
        super(Objects.requireNonNull(center, "center"));
        this.word = Objects.requireNonNull(word, "word");
        this.turns = turns;
        this.radius = radius;
    }

    public int turns() {
        return turns;
    }

    public float radius() {
        return radius;
    }

    @Override
    public String name() {
        return word;
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.at(seq, MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, getPosition(), turns, 0, radius, 0));
    }

    @Override
    public String toString() {
        return word + " " + getPosition() + " turns " + turns + " radius " + radius;
    }
}
