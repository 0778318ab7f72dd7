package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import java.util.List;

/**
 * Start taking pictures: one MAV_CMD_IMAGE_START_CAPTURE in MAV_FRAME_MISSION, its parameters as
 * MAVLink defines them (the original put the interval in p1 and forced p2 = 10).
 * p1 = 0 (all cameras), p2 = interval (s), p3 = number of pictures (0: until {@code stopCapturing}),
 * p4 = 0. {@code capturePhoto} is (0, 1), {@code captureSeveralPhotos n, t} is (t, n),
 * {@code captureUntilStop t} is (t, 0).
 */
public final class CameraPoint extends MissionPoint {

    /** The interval between pictures when none is given, in seconds. */
    public static final float DEFAULT_INTERVAL = 2f;

    private final float interval;
    private final int count;

    public CameraPoint(String word, float interval, int count) {
        super(word, null);
        this.interval = interval;
        this.count = count;
    }

    public float interval() {
        return interval;
    }

    /** The number of pictures; 0 means until stopped. */
    public int count() {
        return count;
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.command(seq, MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, 0, interval, count, 0));
    }

    @Override
    public String toString() {
        return name() + " interval " + interval + " s count " + count;
    }
}
