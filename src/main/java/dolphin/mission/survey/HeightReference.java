package dolphin.mission.survey;

import com.MAVLink.enums.MAV_FRAME;

/** What a survey's altitude is measured from (QGC's DistanceMode, docs/qgc-surveys.md §2.9). */
public enum HeightReference {
    ABOVE_HOME(MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 1),
    ABOVE_SEA_LEVEL(MAV_FRAME.MAV_FRAME_GLOBAL_INT, 2),
    ABOVE_TERRAIN(MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT, 4);

    private final int frame;
    private final int qgcDistanceMode;

    HeightReference(int frame, int qgcDistanceMode) {
        this.frame = frame;
        this.qgcDistanceMode = qgcDistanceMode;
    }

    /** The waypoints' MAV_FRAME. */
    public int frame() {
        return frame;
    }

    /** QGC's AltMode: 1 relative, 2 absolute, 4 terrain frame. */
    public int qgcDistanceMode() {
        return qgcDistanceMode;
    }

    /**
     * The reference of a QGC DistanceMode; 3 (CalcAboveTerrain, waypoints at terrain heights QGC
     * looked up) is read as {@link #ABOVE_TERRAIN}, the vehicle following the terrain itself.
     */
    public static HeightReference ofQgcDistanceMode(int mode) {
        return switch (mode) {
            case 1 -> ABOVE_HOME;
            case 2 -> ABOVE_SEA_LEVEL;
            case 3, 4 -> ABOVE_TERRAIN;
            default -> throw new IllegalArgumentException("a QGroundControl distance mode is 1 (relative), 2 (absolute), "
                    + "3 (calculated above terrain) or 4 (terrain frame), got " + mode);
        };
    }
}
