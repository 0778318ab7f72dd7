package dolphin.mission.model;

import com.MAVLink.enums.MAV_MISSION_TYPE;

/**
 * The three lists the mission protocol transfers (MISSION_COUNT's mission_type), each with its own
 * storage on the vehicle: the mission, the geofence and the rally points (docs/airspace.md). Only a
 * mission has a home at item 0.
 */
public enum MissionType {

    MISSION(MAV_MISSION_TYPE.MAV_MISSION_TYPE_MISSION, "mission"),
    FENCE(MAV_MISSION_TYPE.MAV_MISSION_TYPE_FENCE, "fence"),
    RALLY(MAV_MISSION_TYPE.MAV_MISSION_TYPE_RALLY, "rally points");

    private final int wire;
    private final String label;

    MissionType(int wire, String label) {
        this.wire = wire;
        this.label = label;
    }

    /** The MAV_MISSION_TYPE value on the wire. */
    public int wire() {
        return wire;
    }

    /** "mission", "fence", "rally points": for messages. */
    public String label() {
        return label;
    }

    /** Whether item 0 is the home, which the vehicle replaces with its own. */
    public boolean hasHome() {
        return this == MISSION;
    }

    /** The type of a wire value, or null for one we do not transfer (MAV_MISSION_TYPE_ALL). */
    public static MissionType of(int wire) {
        for (MissionType t : values()) {
            if (t.wire == wire) {
                return t;
            }
        }
        return null;
    }
}
