package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.List;
import java.util.Objects;

/**
 * Take off and climb to a position: one MAV_CMD_NAV_TAKEOFF (commands 4 and 5 of
 * docs/mission-commands.md).
 * p1 = pitch (degrees, default 15), p2 = p3 = 0, p4 = yaw (degrees, default NaN: keep the yaw mode).
 */
public final class TakeOffPoint extends MissionPoint {

    public static final float DEFAULT_PITCH = 15f;

    private final float pitch;
    private final float yaw;
    private final FlightWay way;

    public TakeOffPoint(String word, Position target, float pitch, float yaw) {
        this(word, target, pitch, yaw, FlightWay.AS_THE_VEHICLE_DOES);
    }

    /** A take-off the script says how to fly: the vehicle's rules turn it into the command that does (docs/vtol.md). */
    public TakeOffPoint(String word, Position target, float pitch, float yaw, FlightWay way) {
        super(word, Objects.requireNonNull(target, "target"));
        this.pitch = pitch;
        this.yaw = yaw;
        this.way = Objects.requireNonNull(way, "way");
    }

    public FlightWay way() {
        return way;
    }

    public float pitch() {
        return pitch;
    }

    public float yaw() {
        return yaw;
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.at(seq, MAV_CMD.MAV_CMD_NAV_TAKEOFF, getPosition(), pitch, 0, 0, yaw));
    }

    @Override
    public String toString() {
        return name() + " " + getPosition() + " pitch " + pitch + " yaw " + yaw + " " + way;
    }
}
