package dolphin.mavlink;

import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.enums.MAV_VTOL_STATE;
import com.MAVLink.enums.PLANE_MODE;
import com.MAVLink.enums.ROVER_MODE;
import com.MAVLink.enums.SUB_MODE;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalLong;

/**
 * The kind of ArduPilot vehicle, which decides its mode numbers and how a mission starts, flies and
 * ends (docs/mavlink.md, "How each family flies a mission"). A QuadPlane (VTOL) runs ArduPlane and a
 * traditional helicopter (HELI) ArduCopter, with their modes, but take off, land and start
 * differently (docs/vtol.md). Other autopilots are OTHER: discovered and usable, modes shown as numbers.
 */
public enum VehicleFamily {
    COPTER("ArduCopter", null, COPTER_MODE.class, "COPTER_MODE_"),
    HELI("ArduCopter helicopter", COPTER, COPTER_MODE.class, "COPTER_MODE_"),
    PLANE("ArduPlane", null, PLANE_MODE.class, "PLANE_MODE_"),
    VTOL("ArduPlane VTOL", PLANE, PLANE_MODE.class, "PLANE_MODE_"),
    ROVER("Rover", null, ROVER_MODE.class, "ROVER_MODE_"),
    SUB("ArduSub", null, SUB_MODE.class, "SUB_MODE_"),
    OTHER("other", null, null, null);

    private final String label;
    private final VehicleFamily firmware;
    private final Class<?> modes;
    private final String prefix;

    VehicleFamily(String label, VehicleFamily firmware, Class<?> modes, String prefix) {
        this.label = label;
        this.firmware = firmware;
        this.modes = modes;
        this.prefix = prefix;
    }

    /** The family whose firmware this one runs: ArduPlane for a VTOL, ArduCopter for a helicopter, else itself. */
    public VehicleFamily firmware() {
        return firmware != null ? firmware : this;
    }

    public String label() {
        return label;
    }

    public static VehicleFamily of(int mavType, int autopilot) {
        if (autopilot != MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA) {
            return OTHER;
        }
        return switch (mavType) {
            case MAV_TYPE.MAV_TYPE_FIXED_WING -> PLANE;
            // ArduPlane reports these only when Q_MAV_TYPE says so; by default a QuadPlane is FIXED_WING (withVtolState)
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

    /** All modes of the family, number to name (e.g. 3 -> "AUTO"); empty for OTHER. */
    public Map<Long, String> modes() {
        return modes == null ? Map.of() : EnumNames.of(modes, prefix);
    }

    public String modeName(long customMode) {
        String n = modes().get(customMode);
        return n != null ? n : "mode " + customMode;
    }

    public OptionalLong modeNumber(String name) {
        String wanted = name.toUpperCase(Locale.ROOT);
        return modes().entrySet().stream().filter(e -> e.getValue().equals(wanted))
                .mapToLong(Map.Entry::getKey).findFirst();
    }

    @Override
    public String toString() {
        return label;
    }
}
