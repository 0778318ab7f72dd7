package dolphin.mavlink;

import com.MAVLink.common.msg_sys_status;
import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_MODE_FLAG;
import com.MAVLink.enums.MAV_SYS_STATUS_SENSOR;
import com.MAVLink.enums.PLANE_MODE;
import com.MAVLink.enums.ROVER_MODE;
import com.MAVLink.enums.SUB_MODE;
import java.util.Map;
import java.util.function.Function;
import java.util.function.LongFunction;

/**
 * The autopilot a vehicle runs, the axis beside its {@link VehicleFamily}, as QGroundControl's
 * firmware plugins have it (docs/px4.md, "Autopilots"): its mode tables and how a mode is asked
 * for, how its missions are numbered, and what it offers. What differs between its families' flights
 * is the mission layer's (FlightRules).
 */
public enum Autopilot {
    /**
     * ArduPilot: a mode table per family, DO_SET_MODE with the whole custom_mode in param2, and its
     * home as item 0 of every mission, which MAVLink FTP transfers as the file @MISSION/mission.dat.
     */
    ARDUPILOT("ArduPilot", Autopilot::arduPilotModes, mode -> new float[] {MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, mode},
            "AUTO", true, true, true, true, "PreArm:", false) {
        @Override
        public String label(VehicleFamily family) {
            return switch (family) {
                case COPTER -> "ArduCopter";
                case HELI -> "ArduCopter helicopter";
                case PLANE -> "ArduPlane";
                case VTOL -> "ArduPlane VTOL";
                case ROVER -> "Rover";
                case SUB -> "ArduSub";
                case OTHER -> "ArduPilot";
            };
        }

        @Override
        public boolean tellsVtolByState() {
            return true;
        }
    },
    /**
     * PX4: one mode table, main and sub modes apart in DO_SET_MODE; the first item of a mission is its
     * seq 0, with no home before it; no mission over MAVLink FTP.
     */
    PX4("PX4", family -> Px4Modes.TABLE, mode -> new float[] {MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED,
            Px4Modes.main(mode), Px4Modes.sub(mode)}, "AUTO.MISSION", false, false, false, false, "Preflight Fail:", true),
    /** Any other autopilot: discovered and usable, its modes shown as numbers, missions as ArduPilot numbers them. */
    OTHER("other", family -> ModeTable.NONE, mode -> new float[] {MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, mode},
            "AUTO", true, false, false, true, "PreArm:", false);

    private final String name;
    private final Function<VehicleFamily, ModeTable> modes;
    private final LongFunction<float[]> setMode;
    private final String missionMode;
    private final boolean homeItem;
    private final boolean missionFtp;
    private final boolean requestsAhead;
    private final boolean prearmEnabledBit;
    private final String prearmPrefix;
    private final boolean repeatsItemReached;

    Autopilot(String name, Function<VehicleFamily, ModeTable> modes, LongFunction<float[]> setMode, String missionMode,
              boolean homeItem, boolean missionFtp, boolean requestsAhead, boolean prearmEnabledBit, String prearmPrefix,
              boolean repeatsItemReached) {
        this.name = name;
        this.modes = modes;
        this.setMode = setMode;
        this.missionMode = missionMode;
        this.homeItem = homeItem;
        this.missionFtp = missionFtp;
        this.requestsAhead = requestsAhead;
        this.prearmEnabledBit = prearmEnabledBit;
        this.prearmPrefix = prearmPrefix;
        this.repeatsItemReached = repeatsItemReached;
    }

    /** The autopilot of a HEARTBEAT's autopilot field. */
    public static Autopilot of(int mavAutopilot) {
        return switch (mavAutopilot) {
            case MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA -> ARDUPILOT;
            case MAV_AUTOPILOT.MAV_AUTOPILOT_PX4 -> PX4;
            default -> OTHER;
        };
    }

    /** What a vehicle of the family running this autopilot is called, e.g. "ArduCopter", "PX4 multicopter". */
    public String label(VehicleFamily family) {
        return family == VehicleFamily.OTHER ? name : name + " " + family.noun();
    }

    public ModeTable modes(VehicleFamily family) {
        return modes.apply(family);
    }

    /** Params 1 to 3 of the MAV_CMD_DO_SET_MODE that asks for a mode. */
    public float[] setModeParams(long customMode) {
        return setMode.apply(customMode);
    }

    /**
     * Whether a plane may turn out a VTOL only by EXTENDED_SYS_STATE's vtol_state: an ArduPlane
     * QuadPlane says FIXED_WING in its heartbeat unless Q_MAV_TYPE is set ({@link VehicleFamily#withVtolState});
     * PX4's heartbeat names a VTOL as one.
     */
    public boolean tellsVtolByState() {
        return false;
    }

    /** The mode the vehicle flies its mission in. */
    public String missionMode() {
        return missionMode;
    }

    /** Whether item 0 of a mission is the vehicle's home, uploaded and downloaded with the others. */
    public boolean homeItem() {
        return homeItem;
    }

    /** Whether the vehicle's mission may go over MAVLink FTP, when the vehicle offers FTP at all. */
    public boolean missionFtp() {
        return missionFtp;
    }

    /**
     * Whether a download may ask for several items at once: ArduPilot answers any request in range;
     * PX4 only the next one or the last again, and aborts the transfer on any other
     * (MavlinkMissionManager::handle_mission_request_both), so its items are asked for one at a time.
     */
    public boolean requestsAhead() {
        return requestsAhead;
    }

    /**
     * Whether SYS_STATUS says the vehicle's pre-arm checks fail. ArduPilot reports them as a sensor,
     * enabled, and unhealthy while they fail; PX4 sets only the health bit, while it could arm in
     * its current mode (its SYS_STATUS stream), so a clear bit is a failure there. Unknown before the first SYS_STATUS: not failing.
     */
    public boolean prearmFailing(msg_sys_status status) {
        int bit = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK;
        return status != null && (!prearmEnabledBit || (status.onboard_control_sensors_enabled & bit) != 0)
                && (status.onboard_control_sensors_health & bit) == 0;
    }

    /** How the autopilot's texts about a failing pre-arm check begin: "PreArm:" (ArduPilot), "Preflight Fail:" (PX4). */
    public String prearmPrefix() {
        return prearmPrefix;
    }

    /**
     * Whether the vehicle sends each MISSION_ITEM_REACHED again after the first: PX4 sends the latest ten
     * more times, a second apart (MavlinkMissionManager::send), after its mission has ended too.
     */
    public boolean repeatsItemReached() {
        return repeatsItemReached;
    }

    /**
     * A mission item's seq as the runtime numbers it, home 0 and the first item 1, from the seq the
     * vehicle sends (MISSION_CURRENT, MISSION_ITEM_REACHED).
     */
    public int missionSeq(int vehicleSeq) {
        return homeItem ? vehicleSeq : vehicleSeq + 1;
    }

    /** The seq the vehicle knows a mission item by (MISSION_SET_CURRENT, DO_JUMP), from the runtime's. */
    public int vehicleSeq(int missionSeq) {
        return homeItem ? missionSeq : missionSeq - 1;
    }

    @Override
    public String toString() {
        return name;
    }

    private static ModeTable arduPilotModes(VehicleFamily family) {
        return ArduPilotTables.TABLES.getOrDefault(family.firmware(), ModeTable.NONE);
    }

    /** ArduPilot's mode tables by firmware, made once, on first use. */
    private static final class ArduPilotTables {
        static final Map<VehicleFamily, ModeTable> TABLES = Map.of(
                VehicleFamily.COPTER, new ModeTable(EnumNames.of(COPTER_MODE.class, "COPTER_MODE_")),
                VehicleFamily.PLANE, new ModeTable(EnumNames.of(PLANE_MODE.class, "PLANE_MODE_")),
                VehicleFamily.ROVER, new ModeTable(EnumNames.of(ROVER_MODE.class, "ROVER_MODE_")),
                VehicleFamily.SUB, new ModeTable(EnumNames.of(SUB_MODE.class, "SUB_MODE_")));
    }
}
