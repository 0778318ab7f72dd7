package dolphin.mavlink;

import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.enums.PLANE_MODE;
import com.MAVLink.enums.ROVER_MODE;
import com.MAVLink.enums.SUB_MODE;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalLong;

/**
 * The ArduPilot firmware a vehicle runs, which decides its mode numbers and how a mission starts
 * (docs/mavlink.md, "How each family flies a mission"). Other autopilots are OTHER: discovered and
 * usable, modes shown as numbers.
 */
public enum VehicleFamily {
    COPTER("ArduCopter", COPTER_MODE.class, "COPTER_MODE_"),
    PLANE("ArduPlane", PLANE_MODE.class, "PLANE_MODE_"),
    ROVER("Rover", ROVER_MODE.class, "ROVER_MODE_"),
    SUB("ArduSub", SUB_MODE.class, "SUB_MODE_"),
    OTHER("other", null, null);

    private final String label;
    private final Class<?> modes;
    private final String prefix;

    VehicleFamily(String label, Class<?> modes, String prefix) {
        this.label = label;
        this.modes = modes;
        this.prefix = prefix;
    }

    public String label() {
        return label;
    }

    public static VehicleFamily of(int mavType, int autopilot) {
        if (autopilot != MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA) {
            return OTHER;
        }
        return switch (mavType) {
            case MAV_TYPE.MAV_TYPE_FIXED_WING, MAV_TYPE.MAV_TYPE_VTOL_DUOROTOR, MAV_TYPE.MAV_TYPE_VTOL_QUADROTOR,
                 MAV_TYPE.MAV_TYPE_VTOL_TILTROTOR, MAV_TYPE.MAV_TYPE_VTOL_RESERVED2, MAV_TYPE.MAV_TYPE_VTOL_RESERVED3,
                 MAV_TYPE.MAV_TYPE_VTOL_RESERVED4, MAV_TYPE.MAV_TYPE_VTOL_RESERVED5 -> PLANE;
            case MAV_TYPE.MAV_TYPE_QUADROTOR, MAV_TYPE.MAV_TYPE_COAXIAL, MAV_TYPE.MAV_TYPE_HELICOPTER, MAV_TYPE.MAV_TYPE_HEXAROTOR,
                 MAV_TYPE.MAV_TYPE_OCTOROTOR, MAV_TYPE.MAV_TYPE_TRICOPTER, MAV_TYPE.MAV_TYPE_DODECAROTOR,
                 MAV_TYPE.MAV_TYPE_DECAROTOR, MAV_TYPE.MAV_TYPE_GENERIC_MULTIROTOR -> COPTER;
            case MAV_TYPE.MAV_TYPE_GROUND_ROVER, MAV_TYPE.MAV_TYPE_SURFACE_BOAT -> ROVER;
            case MAV_TYPE.MAV_TYPE_SUBMARINE -> SUB;
            default -> OTHER;
        };
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
