package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.List;
import java.util.Objects;

/**
 * Land at a position: one MAV_CMD_NAV_LAND (commands 17 and 20 of docs/mission-commands.md).
 * p1 = 0 (abort altitude: the vehicle's default), p2 = precision land mode (PRECISION_LAND_MODE:
 * 0 disabled, 1 opportunistic, 2 required), p3 = 0, p4 = yaw (degrees, NaN: keep the yaw mode).
 */
public final class LandingPoint extends MissionPoint {

    private final float yaw;
    private final int landMode;
    private final FlightWay way;

    public LandingPoint(String word, Position target, float yaw, int landMode) {
        this(word, target, yaw, landMode, FlightWay.AS_THE_VEHICLE_DOES);
    }

    /** A landing the script says how to fly: the vehicle's rules turn it into the command that does (docs/vtol.md). */
    public LandingPoint(String word, Position target, float yaw, int landMode, FlightWay way) {
        super(word, Objects.requireNonNull(target, "target"));
        this.yaw = yaw;
        this.landMode = landMode;
        this.way = Objects.requireNonNull(way, "way");
    }

    public FlightWay way() {
        return way;
    }

    public float yaw() {
        return yaw;
    }

    public int landMode() {
        return landMode;
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.at(seq, MAV_CMD.MAV_CMD_NAV_LAND, getPosition(), 0, landMode, 0, yaw));
    }

    @Override
    public String toString() {
        return name() + " " + getPosition() + " yaw " + yaw + " mode " + landMode + " " + way;
    }
}
