package dolphin.sim;

import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.PLANE_MODE;
import com.MAVLink.enums.ROVER_MODE;
import com.MAVLink.enums.SUB_MODE;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.ModeTable;
import dolphin.mavlink.Px4Modes;
import dolphin.mavlink.VehicleFamily;
import java.util.OptionalInt;

/**
 * The modes a simulated vehicle boots in and flies by, for its autopilot and family: the one it boots
 * in, the one that flies its mission, the RTL that a fence breach and MAV_CMD_NAV_RETURN_TO_LAUNCH
 * switch to (none on ArduSub) and the one MAV_CMD_NAV_LAND switches to (none where the firmware does
 * not take that command).
 */
record SimModes(Autopilot autopilot, ModeTable table, int boot, int auto, OptionalInt rtl, OptionalInt land) {

    private static final SimModes COPTER = arduPilot(VehicleFamily.COPTER, COPTER_MODE.COPTER_MODE_STABILIZE,
            COPTER_MODE.COPTER_MODE_AUTO, OptionalInt.of(COPTER_MODE.COPTER_MODE_RTL), OptionalInt.of(COPTER_MODE.COPTER_MODE_LAND));
    private static final SimModes PLANE = arduPilot(VehicleFamily.PLANE, PLANE_MODE.PLANE_MODE_MANUAL, PLANE_MODE.PLANE_MODE_AUTO,
            OptionalInt.of(PLANE_MODE.PLANE_MODE_RTL), OptionalInt.empty());
    /**
     * quadplane.parm's flight mode switch (FLTMODE_CH 5, FLTMODE4 FLY_BY_WIRE_A) at SITL's RC 5 of
     * 1500 (position 4): SITL's QuadPlane was in FLY_BY_WIRE_A from the recordings' first heartbeat.
     */
    private static final SimModes QUADPLANE = arduPilot(VehicleFamily.PLANE, PLANE_MODE.PLANE_MODE_FLY_BY_WIRE_A,
            PLANE_MODE.PLANE_MODE_AUTO, OptionalInt.of(PLANE_MODE.PLANE_MODE_RTL), OptionalInt.empty());
    private static final SimModes ROVER = arduPilot(VehicleFamily.ROVER, ROVER_MODE.ROVER_MODE_MANUAL, ROVER_MODE.ROVER_MODE_AUTO,
            OptionalInt.of(ROVER_MODE.ROVER_MODE_RTL), OptionalInt.empty());
    /** GCS_MAVLINK_Sub::handle_MAV_CMD_NAV_LAND: SURFACE. */
    private static final SimModes SUB = arduPilot(VehicleFamily.SUB, SUB_MODE.SUB_MODE_MANUAL, SUB_MODE.SUB_MODE_AUTO,
            OptionalInt.empty(), OptionalInt.of(SUB_MODE.SUB_MODE_SURFACE));
    /** PX4's, whatever the family: it boots holding (AUTO.LOITER), as SITL did from its first heartbeat. */
    private static final SimModes PX4 = new SimModes(Autopilot.PX4, Px4Modes.TABLE, px4(Px4Modes.AUTO_LOITER),
            px4(Px4Modes.AUTO_MISSION), OptionalInt.of(px4(Px4Modes.AUTO_RTL)), OptionalInt.of(px4(Px4Modes.AUTO_LAND)));

    static SimModes of(Autopilot autopilot, VehicleFamily family) {
        if (autopilot == Autopilot.PX4) {
            return PX4;
        }
        return switch (family) {
            case PLANE -> PLANE;
            case VTOL -> QUADPLANE;
            case ROVER -> ROVER;
            case SUB -> SUB;
            default -> COPTER;
        };
    }

    private static SimModes arduPilot(VehicleFamily firmware, int boot, int auto, OptionalInt rtl, OptionalInt land) {
        return new SimModes(Autopilot.ARDUPILOT, Autopilot.ARDUPILOT.modes(firmware), boot, auto, rtl, land);
    }

    private static int px4(int autoSubMode) {
        return (int) Px4Modes.customMode(Px4Modes.MAIN_AUTO, autoSubMode);
    }
}
