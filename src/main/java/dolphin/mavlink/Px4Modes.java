package dolphin.mavlink;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * PX4's flight modes (PX4-Autopilot's px4_custom_mode.h): HEARTBEAT custom_mode packs a main mode in
 * bits 16 to 23 and a sub mode in bits 24 to 31. MAV_CMD_DO_SET_MODE takes them apart, as param2 and
 * param3: a whole custom_mode in param2 is acknowledged and ignored (docs/px4.md). Named as PX4's own
 * commander names them, main mode and sub mode joined by a dot (AUTO.MISSION).
 */
public final class Px4Modes {

    public static final int MAIN_MANUAL = 1;
    public static final int MAIN_ALTCTL = 2;
    public static final int MAIN_POSCTL = 3;
    public static final int MAIN_AUTO = 4;
    public static final int MAIN_ACRO = 5;
    public static final int MAIN_OFFBOARD = 6;
    public static final int MAIN_STABILIZED = 7;
    public static final int MAIN_TERMINATION = 10;

    public static final int AUTO_READY = 1;
    public static final int AUTO_TAKEOFF = 2;
    public static final int AUTO_LOITER = 3;
    public static final int AUTO_MISSION = 4;
    public static final int AUTO_RTL = 5;
    public static final int AUTO_LAND = 6;
    public static final int AUTO_FOLLOW_TARGET = 8;
    public static final int AUTO_PRECLAND = 9;
    public static final int AUTO_VTOL_TAKEOFF = 10;
    public static final int POSCTL_ORBIT = 1;

    public static final ModeTable TABLE = table();

    private Px4Modes() {
    }

    /** The custom_mode of a main mode and sub mode. */
    public static long customMode(int main, int sub) {
        return ((long) main << 16) | ((long) sub << 24);
    }

    public static int main(long customMode) {
        return (int) (customMode >> 16) & 0xff;
    }

    public static int sub(long customMode) {
        return (int) (customMode >> 24) & 0xff;
    }

    private static ModeTable table() {
        Map<Long, String> names = new LinkedHashMap<>();
        names.put(customMode(MAIN_MANUAL, 0), "MANUAL");
        names.put(customMode(MAIN_ALTCTL, 0), "ALTCTL");
        names.put(customMode(MAIN_POSCTL, 0), "POSCTL");
        names.put(customMode(MAIN_POSCTL, POSCTL_ORBIT), "POSCTL.ORBIT");
        names.put(customMode(MAIN_ACRO, 0), "ACRO");
        names.put(customMode(MAIN_OFFBOARD, 0), "OFFBOARD");
        names.put(customMode(MAIN_STABILIZED, 0), "STABILIZED");
        names.put(customMode(MAIN_TERMINATION, 0), "TERMINATION");
        names.put(customMode(MAIN_AUTO, AUTO_READY), "AUTO.READY");
        names.put(customMode(MAIN_AUTO, AUTO_TAKEOFF), "AUTO.TAKEOFF");
        names.put(customMode(MAIN_AUTO, AUTO_LOITER), "AUTO.LOITER");
        names.put(customMode(MAIN_AUTO, AUTO_MISSION), "AUTO.MISSION");
        names.put(customMode(MAIN_AUTO, AUTO_RTL), "AUTO.RTL");
        names.put(customMode(MAIN_AUTO, AUTO_LAND), "AUTO.LAND");
        names.put(customMode(MAIN_AUTO, AUTO_FOLLOW_TARGET), "AUTO.FOLLOW_TARGET");
        names.put(customMode(MAIN_AUTO, AUTO_PRECLAND), "AUTO.PRECLAND");
        names.put(customMode(MAIN_AUTO, AUTO_VTOL_TAKEOFF), "AUTO.VTOL_TAKEOFF");
        return new ModeTable(names);
    }
}
