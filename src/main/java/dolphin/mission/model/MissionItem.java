package dolphin.mission.model;

import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.core.Position;
import dolphin.mavlink.EnumNames;

/**
 * One item of a MAVLink mission as it goes on the wire (MISSION_ITEM_INT): x and y are latitude
 * and longitude in degE7, z is metres (above mean sea level in MAV_FRAME_GLOBAL_INT, the frame this
 * project uses: docs/decisions.md, "Heights and positions"). Immutable; equal items compare equal,
 * NaN parameters included.
 */
public record MissionItem(int seq, int command, int frame, float param1, float param2, float param3, float param4,
                          int x, int y, float z, boolean autocontinue) {

    public static final int GLOBAL_INT = MAV_FRAME.MAV_FRAME_GLOBAL_INT;
    /** For commands without a position (MAV_FRAME_MISSION). */
    public static final int MISSION = MAV_FRAME.MAV_FRAME_MISSION;

    /** An item at a position, in MAV_FRAME_GLOBAL_INT. */
    public static MissionItem at(int seq, int command, Position p, float p1, float p2, float p3, float p4) {
        return new MissionItem(seq, command, GLOBAL_INT, p1, p2, p3, p4, degE7(p.latitudeDegrees()),
                degE7(p.longitudeDegrees()), (float) p.hae(), true);
    }

    /** An item without a position (DO commands, NAV_DELAY), in MAV_FRAME_MISSION. */
    public static MissionItem command(int seq, int command, float p1, float p2, float p3, float p4) {
        return new MissionItem(seq, command, MISSION, p1, p2, p3, p4, 0, 0, 0, true);
    }

    public static int degE7(double degrees) {
        return (int) Math.round(degrees * 1e7);
    }

    /**
     * What a frame's z is measured from: the frame without its _INT variant (GLOBAL_INT is GLOBAL).
     * ArduPilot stores this, not the frame an item was sent in.
     */
    public static int altitudeReference(int frame) {
        return switch (frame) {
            case MAV_FRAME.MAV_FRAME_GLOBAL_INT -> MAV_FRAME.MAV_FRAME_GLOBAL;
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT -> MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT;
            case MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT -> MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT;
            default -> frame;
        };
    }

    public MissionItem withSeq(int newSeq) {
        return new MissionItem(newSeq, command, frame, param1, param2, param3, param4, x, y, z, autocontinue);
    }

    /** The position of a positional item (latitude, longitude, z as height). */
    public Position position() {
        return Position.fromDegrees(x * 1e-7, y * 1e-7, z);
    }

    public String commandName() {
        return EnumNames.name(MAV_CMD.class, "MAV_CMD_", command);
    }

    public String frameName() {
        return EnumNames.name(MAV_FRAME.class, "MAV_FRAME_", frame);
    }

    public msg_mission_item_int toMessage(int targetSystem, int targetComponent) {
        return toMessage(targetSystem, targetComponent, MissionType.MISSION);
    }

    public msg_mission_item_int toMessage(int targetSystem, int targetComponent, MissionType type) {
        msg_mission_item_int m = new msg_mission_item_int();
        m.target_system = (short) targetSystem;
        m.target_component = (short) targetComponent;
        m.seq = seq;
        m.command = command;
        m.frame = (short) frame;
        m.param1 = param1;
        m.param2 = param2;
        m.param3 = param3;
        m.param4 = param4;
        m.x = x;
        m.y = y;
        m.z = z;
        m.autocontinue = (short) (autocontinue ? 1 : 0);
        m.current = 0;
        m.mission_type = (short) type.wire();
        return m;
    }

    public static MissionItem fromMessage(msg_mission_item_int m) {
        return new MissionItem(m.seq, m.command, m.frame, m.param1, m.param2, m.param3, m.param4, m.x, m.y, m.z,
                m.autocontinue != 0);
    }
}
