package dolphin.mavlink.mission;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.List;
import java.util.Objects;

/**
 * Circle a position for a time: one MAV_CMD_NAV_LOITER_TIME (reference C.6 rows 10, 13, 16).
 * p1 = seconds, p2 = 0, p3 = radius (metres, clockwise), p4 = 0 (exit at the centre).
 */
public final class LoiterTimePoint extends MissionPoint {

    private final String word;
    private final int seconds;
    private final float radius;

    public LoiterTimePoint(String word, Position center, int seconds, float radius) {
        super(Objects.requireNonNull(center, "center"));
        this.word = Objects.requireNonNull(word, "word");
        this.seconds = seconds;
        this.radius = radius;
    }

    public int seconds() {
        return seconds;
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
        return List.of(MissionItem.at(seq, MAV_CMD.MAV_CMD_NAV_LOITER_TIME, getPosition(), seconds, 0, radius, 0));
    }

    @Override
    public String toString() {
        return word + " " + getPosition() + " " + seconds + " s radius " + radius;
    }
}
