package dolphin.sim;

import com.MAVLink.enums.MAV_TYPE;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.VehicleFamily;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * The simulated firmwares; what each one does is its {@link Firmware}. Each vehicle runs a firmware
 * of its own ({@link #newFirmware}): a QuadPlane's and a helicopter's keep what their rotors are doing.
 */
public enum VehicleKind {
    COPTER(CopterFirmware::new),
    PLANE(PlaneFirmware::new),
    ROVER(() -> new RoverFirmware(MAV_TYPE.MAV_TYPE_GROUND_ROVER)),
    /** ArduRover's motorboat: a rover on the water. */
    BOAT(() -> new RoverFirmware(MAV_TYPE.MAV_TYPE_SURFACE_BOAT)),
    SUB(SubFirmware::new),
    /** ArduPlane with Q_ENABLE 1: a QuadPlane, SITL's {@code --model quadplane}. */
    QUADPLANE(QuadPlaneFirmware::new),
    /** ArduCopter's traditional helicopter, SITL's {@code --model heli}. */
    HELI(HeliFirmware::new);

    private final Supplier<Firmware> make;
    /** One firmware that no vehicle runs, for what the kind is: its family, its faults. */
    private final Firmware firmware;

    VehicleKind(Supplier<Firmware> make) {
        this.make = make;
        this.firmware = make.get();
    }

    /** Whether the fleet simulates this type under {@code autopilot}: PX4 flies copters, planes and standard VTOLs. */
    public boolean simulatedOn(Autopilot autopilot) {
        return autopilot == Autopilot.ARDUPILOT || autopilot == Autopilot.PX4 && (this == COPTER || this == PLANE || this == QUADPLANE);
    }

    /** The types the fleet simulates under {@code autopilot}. */
    public static List<VehicleKind> simulatedFor(Autopilot autopilot) {
        return Arrays.stream(values()).filter(k -> k.simulatedOn(autopilot)).toList();
    }

    public VehicleFamily family() {
        return firmware.family();
    }

    Firmware firmware() {
        return firmware;
    }

    /** The firmware one vehicle runs. */
    Firmware newFirmware() {
        return make.get();
    }

    public static VehicleKind parse(String s) {
        return switch (s.toLowerCase(Locale.ROOT)) {
            case "copter", "arducopter" -> COPTER;
            case "plane", "arduplane" -> PLANE;
            case "rover", "ardurover" -> ROVER;
            case "boat" -> BOAT;
            case "sub", "ardusub" -> SUB;
            case "quadplane", "vtol" -> QUADPLANE;
            case "heli", "helicopter" -> HELI;
            default -> throw new IllegalArgumentException("unknown vehicle type '" + s
                    + "': expected copter, plane, rover, boat, sub, quadplane or heli");
        };
    }
}
