package dolphin.mavlink;

import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.enums.MAV_VTOL_STATE;

/**
 * The kind of vehicle, which with its {@link Autopilot} decides its mode numbers and how a mission
 * starts, flies and ends (docs/mavlink.md, "How each family flies a mission"). On ArduPilot a
 * QuadPlane (VTOL) runs ArduPlane and a traditional helicopter (HELI) ArduCopter, with their modes,
 * but take off, land and start differently (docs/vtol.md). A vehicle of another autopilot than
 * ArduPilot and PX4, or of a kind neither flies, is OTHER: discovered and usable, modes shown as numbers.
 */
public enum VehicleFamily {
    COPTER("multicopter", null),
    HELI("helicopter", COPTER),
    PLANE("fixed-wing", null),
    VTOL("VTOL", PLANE),
    ROVER("rover", null),
    SUB("submarine", null),
    OTHER("vehicle", null);

    private final String noun;
    private final VehicleFamily firmware;

    VehicleFamily(String noun, VehicleFamily firmware) {
        this.noun = noun;
        this.firmware = firmware;
    }

    /** The family whose ArduPilot firmware this one runs: ArduPlane for a VTOL, ArduCopter for a helicopter, else itself. */
    public VehicleFamily firmware() {
        return firmware != null ? firmware : this;
    }

    /** What the family is called whatever its autopilot, e.g. "multicopter". */
    public String noun() {
        return noun;
    }

    /** The family of a HEARTBEAT's MAV_TYPE from ArduPilot or PX4; OTHER from any other autopilot. */
    public static VehicleFamily of(int mavType, int autopilot) {
        if (Autopilot.of(autopilot) == Autopilot.OTHER) {
            return OTHER;
        }
        return switch (mavType) {
            case MAV_TYPE.MAV_TYPE_FIXED_WING -> PLANE;
            // ArduPlane reports these only when Q_MAV_TYPE says so, by default a QuadPlane is FIXED_WING (withVtolState);
            // PX4 always (VTOL_RESERVED2 is its standard VTOL, MAV_TYPE_VTOL_FIXEDROTOR in newer dialects)
            case MAV_TYPE.MAV_TYPE_VTOL_DUOROTOR, MAV_TYPE.MAV_TYPE_VTOL_QUADROTOR,
                 MAV_TYPE.MAV_TYPE_VTOL_TILTROTOR, MAV_TYPE.MAV_TYPE_VTOL_RESERVED2, MAV_TYPE.MAV_TYPE_VTOL_RESERVED3,
                 MAV_TYPE.MAV_TYPE_VTOL_RESERVED4, MAV_TYPE.MAV_TYPE_VTOL_RESERVED5 -> VTOL;
            case MAV_TYPE.MAV_TYPE_HELICOPTER -> HELI;
            case MAV_TYPE.MAV_TYPE_QUADROTOR, MAV_TYPE.MAV_TYPE_COAXIAL, MAV_TYPE.MAV_TYPE_HEXAROTOR,
                 MAV_TYPE.MAV_TYPE_OCTOROTOR, MAV_TYPE.MAV_TYPE_TRICOPTER, MAV_TYPE.MAV_TYPE_DODECAROTOR,
                 MAV_TYPE.MAV_TYPE_DECAROTOR, MAV_TYPE.MAV_TYPE_GENERIC_MULTIROTOR -> COPTER;
            case MAV_TYPE.MAV_TYPE_GROUND_ROVER, MAV_TYPE.MAV_TYPE_SURFACE_BOAT -> ROVER;
            case MAV_TYPE.MAV_TYPE_SUBMARINE -> SUB;
            default -> OTHER;
        };
    }

    /**
     * The family once the vehicle's EXTENDED_SYS_STATE said its VTOL state: ArduPlane reports one
     * other than UNDEFINED only while its QuadPlane code runs (Q_ENABLE set, and rebooted since:
     * GCS_MAVLINK_Plane::vtol_state), though its heartbeat says FIXED_WING unless Q_MAV_TYPE is set.
     */
    public VehicleFamily withVtolState(int vtolState) {
        return this == PLANE && vtolState != MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED ? VTOL : this;
    }
}
