package dolphin.sim;

import com.MAVLink.enums.MAV_TYPE;
import dolphin.mavlink.VehicleFamily;
import java.util.Locale;

/** The simulated firmwares; what each one does is its {@link Firmware}. */
public enum VehicleKind {
    COPTER(new CopterFirmware()),
    PLANE(new PlaneFirmware()),
    ROVER(new RoverFirmware(MAV_TYPE.MAV_TYPE_GROUND_ROVER)),
    /** ArduRover's motorboat: a rover on the water. */
    BOAT(new RoverFirmware(MAV_TYPE.MAV_TYPE_SURFACE_BOAT)),
    SUB(new SubFirmware());

    private final Firmware firmware;

    VehicleKind(Firmware firmware) {
        this.firmware = firmware;
    }

    public VehicleFamily family() {
        return firmware.family();
    }

    Firmware firmware() {
        return firmware;
    }

    public static VehicleKind parse(String s) {
        return switch (s.toLowerCase(Locale.ROOT)) {
            case "copter", "arducopter" -> COPTER;
            case "plane", "arduplane" -> PLANE;
            case "rover", "ardurover" -> ROVER;
            case "boat" -> BOAT;
            case "sub", "ardusub" -> SUB;
            default -> throw new IllegalArgumentException("unknown vehicle type '" + s
                    + "': expected copter, plane, rover, boat or sub");
        };
    }
}
