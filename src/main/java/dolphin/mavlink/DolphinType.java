package dolphin.mavlink;

import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_TYPE;

/**
 * Which heartbeats are vehicles, and their Dolphin type: "UAV" for aircraft, "UGV" ground rovers,
 * "USV" boats, "UUV" submarines (docs/decisions.md, "The link").
 */
public final class DolphinType {

    private DolphinType() {
    }

    /** The Dolphin type of a heartbeat's MAV_TYPE and autopilot, or null when it is not a vehicle. */
    public static String of(int mavType, int autopilot) {
        if (autopilot == MAV_AUTOPILOT.MAV_AUTOPILOT_INVALID) {
            return null;
        }
        return switch (mavType) {
            case MAV_TYPE.MAV_TYPE_GROUND_ROVER -> "UGV";
            case MAV_TYPE.MAV_TYPE_SURFACE_BOAT -> "USV";
            case MAV_TYPE.MAV_TYPE_SUBMARINE -> "UUV";
            case MAV_TYPE.MAV_TYPE_FIXED_WING, MAV_TYPE.MAV_TYPE_QUADROTOR, MAV_TYPE.MAV_TYPE_COAXIAL,
                 MAV_TYPE.MAV_TYPE_HELICOPTER, MAV_TYPE.MAV_TYPE_AIRSHIP, MAV_TYPE.MAV_TYPE_FREE_BALLOON,
                 MAV_TYPE.MAV_TYPE_HEXAROTOR, MAV_TYPE.MAV_TYPE_OCTOROTOR, MAV_TYPE.MAV_TYPE_TRICOPTER,
                 MAV_TYPE.MAV_TYPE_FLAPPING_WING, MAV_TYPE.MAV_TYPE_KITE, MAV_TYPE.MAV_TYPE_VTOL_DUOROTOR,
                 MAV_TYPE.MAV_TYPE_VTOL_QUADROTOR, MAV_TYPE.MAV_TYPE_VTOL_TILTROTOR, MAV_TYPE.MAV_TYPE_VTOL_RESERVED2,
                 MAV_TYPE.MAV_TYPE_VTOL_RESERVED3, MAV_TYPE.MAV_TYPE_VTOL_RESERVED4, MAV_TYPE.MAV_TYPE_VTOL_RESERVED5,
                 MAV_TYPE.MAV_TYPE_PARAFOIL, MAV_TYPE.MAV_TYPE_DODECAROTOR, MAV_TYPE.MAV_TYPE_DECAROTOR,
                 MAV_TYPE.MAV_TYPE_GENERIC_MULTIROTOR, MAV_TYPE.MAV_TYPE_VTOL_GYRODYNE -> "UAV";
            default -> null;
        };
    }
}
