package dolphin.sim;

import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.enums.PLANE_MODE;
import dolphin.mavlink.VehicleFamily;

/** The simulated firmwares, with the numbers ArduPilot uses (ardupilot-behaviour.md). */
public enum VehicleKind {
    COPTER(MAV_TYPE.MAV_TYPE_QUADROTOR, VehicleFamily.COPTER, COPTER_MODE.COPTER_MODE_STABILIZE,
            COPTER_MODE.COPTER_MODE_AUTO, COPTER_MODE.COPTER_MODE_GUIDED, COPTER_MODE.COPTER_MODE_RTL, 0),
    PLANE(MAV_TYPE.MAV_TYPE_FIXED_WING, VehicleFamily.PLANE, PLANE_MODE.PLANE_MODE_MANUAL,
            PLANE_MODE.PLANE_MODE_AUTO, PLANE_MODE.PLANE_MODE_GUIDED, PLANE_MODE.PLANE_MODE_RTL, 1);

    final int mavType;
    final VehicleFamily family;
    final int bootMode;
    final int autoMode;
    final int guidedMode;
    final int rtlMode;
    /** Streams a vehicle sends before anyone asks: copter none, plane 1 Hz (ardupilot-behaviour.md). */
    final double defaultStreamHz;

    VehicleKind(int mavType, VehicleFamily family, int bootMode, int autoMode, int guidedMode, int rtlMode, double defaultStreamHz) {
        this.mavType = mavType;
        this.family = family;
        this.bootMode = bootMode;
        this.autoMode = autoMode;
        this.guidedMode = guidedMode;
        this.rtlMode = rtlMode;
        this.defaultStreamHz = defaultStreamHz;
    }

    public VehicleFamily family() {
        return family;
    }

    public static VehicleKind parse(String s) {
        return switch (s.toLowerCase(java.util.Locale.ROOT)) {
            case "copter", "arducopter" -> COPTER;
            case "plane", "arduplane" -> PLANE;
            default -> throw new IllegalArgumentException("unknown vehicle type '" + s + "': expected copter or plane");
        };
    }
}
