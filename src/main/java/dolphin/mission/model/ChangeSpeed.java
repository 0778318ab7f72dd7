package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import java.util.List;

/**
 * {@code speed(newSpeed, speedType = 0)}: one MAV_CMD_DO_CHANGE_SPEED in MAV_FRAME_MISSION, as
 * MAVLink defines it. p1 = speed type (0 airspeed, 1 ground speed, 2 climb, 3 descent),
 * p2 = speed (m/s), p3 = -1 (throttle unchanged; the original forced 10 %), p4 = 0.
 */
public final class ChangeSpeed extends MissionPoint {

    /** Airspeed: the report and the original's command list say 0 (its code used 1, ground speed). */
    public static final int DEFAULT_TYPE = 0;

    private final float speed;
    private final int type;

    public ChangeSpeed(float speed, int type) {
        super("speed", null);
        this.speed = speed;
        this.type = type;
    }

    public float speed() {
        return speed;
    }

    public int type() {
        return type;
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.command(seq, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, type, speed, -1, 0));
    }

    @Override
    public String toString() {
        return "speed " + speed + " m/s type " + type;
    }
}
