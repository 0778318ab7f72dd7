package dolphin.mavlink.mission;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.List;
import java.util.Objects;

/**
 * Circle a position until the mission is cut short: one MAV_CMD_NAV_LOITER_UNLIM (reference C.6
 * rows 8, 11, 14, 19). p1 = p2 = 0, p3 = radius (metres, clockwise), p4 = 0.
 */
public final class LoiterPoint extends MissionPoint {

    /** The loiter radius the original builder uses when none is given, in metres. */
    public static final float DEFAULT_RADIUS = 15f;

    private final String word;
    private final float radius;

    public LoiterPoint(String word, Position center, float radius) {
        super(Objects.requireNonNull(center, "center"));
        this.word = Objects.requireNonNull(word, "word");
        this.radius = radius;
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
        return List.of(MissionItem.at(seq, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, getPosition(), 0, 0, radius, 0));
    }

    @Override
    public String toString() {
        return word + " " + getPosition() + " radius " + radius;
    }
}
