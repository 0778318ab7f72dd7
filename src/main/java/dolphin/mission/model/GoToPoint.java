package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.List;
import java.util.Objects;

/**
 * Fly to a position: one MAV_CMD_NAV_WAYPOINT (command 3 of docs/mission-commands.md). Made by
 * {@code goPos}, {@code move}, {@code moveFromHome}, {@code returnHome} and {@code altitude}.
 * p1 = 0 (no hold), p2 = 50 m acceptance radius, p3 = 0 (pass through), p4 = NaN (keep the yaw mode).
 */
public final class GoToPoint extends MissionPoint {

    /** The acceptance radius of the original plugin, in metres. */
    public static final float ACCEPTANCE_RADIUS = 50f;

    public GoToPoint(String word, Position target) {
        super(word, Objects.requireNonNull(target, "target"));
    }

    public GoToPoint(Position target) {
        this("goPos", target);
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.at(seq, MAV_CMD.MAV_CMD_NAV_WAYPOINT, getPosition(), 0, ACCEPTANCE_RADIUS, 0, Float.NaN));
    }

    @Override
    public String toString() {
        return name() + " " + getPosition();
    }
}
