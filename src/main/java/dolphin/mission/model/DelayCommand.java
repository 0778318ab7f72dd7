package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import java.util.List;

/**
 * {@code delay(seconds)}: one MAV_CMD_NAV_DELAY in MAV_FRAME_MISSION, as MAVLink defines it:
 * p1 = seconds, p2 = p3 = p4 = -1 (no time of day). The original left p1 at 0 and split the time
 * into h/m/s, with the hours in p3.
 */
public final class DelayCommand extends MissionPoint {

    private final float seconds;

    public DelayCommand(float seconds) {
        super("delay", null);
        this.seconds = seconds;
    }

    public float seconds() {
        return seconds;
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.command(seq, MAV_CMD.MAV_CMD_NAV_DELAY, seconds, -1, -1, -1));
    }

    @Override
    public String toString() {
        return "delay " + seconds + " s";
    }
}
