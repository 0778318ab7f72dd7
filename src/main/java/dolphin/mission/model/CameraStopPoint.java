package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import java.util.List;

/** {@code stopCapturing()}: one MAV_CMD_IMAGE_STOP_CAPTURE in MAV_FRAME_MISSION, every parameter 0. */
public final class CameraStopPoint extends MissionPoint {

    public CameraStopPoint() {
        super("stopCapturing", null);
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.command(seq, MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE, 0, 0, 0, 0));
    }

    @Override
    public String toString() {
        return "stopCapturing";
    }
}
