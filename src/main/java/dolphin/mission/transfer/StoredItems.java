package dolphin.mission.transfer;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import com.MAVLink.enums.MAV_MOUNT_MODE;
import dolphin.core.Position;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * What ArduPilot gives back of a mission item it stored: AP_Mission keeps each command in a few
 * bytes (AP_Mission::mavlink_int_to_mission_cmd) and rebuilds the item from them on download
 * (mission_cmd_to_mavlink_int), so a parameter it does not keep comes back 0, one kept in an
 * integer comes back truncated, a location's height comes back in whole centimetres and its frame
 * as GLOBAL, GLOBAL_RELATIVE_ALT or GLOBAL_TERRAIN_ALT, and a command without a location has x, y
 * and z 0 and frame GLOBAL. Only ArduPlane keeps a NAV_WAYPOINT's acceptance radius and pass-by
 * distance (as whole metres up to 255) instead of its hold time. Integer fields take a float as C
 * does on x86 SITL: truncated towards zero, then cut to the field's width. Item 0 of a mission is
 * the vehicle's home. A fence keeps of each item its command, param1 (none for the return point)
 * and position; a rally point its position, altitude reference and whole metres of height.
 *
 * <p>The simulated vehicles answer downloads with these items, and an FTP upload predicts from them
 * the file the vehicle will read back ({@link #file}), so the recordings of SITL that pin the
 * simulator's answers pin the prediction too.
 */
public final class StoredItems {

    /** Commands with a location, whose frame and x, y, z ArduPilot keeps. */
    public static final Set<Integer> POSITIONAL = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM,
            MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_LAND,
            MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_NAV_CONTINUE_AND_CHANGE_ALT, MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT,
            MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, MAV_CMD.MAV_CMD_DO_SET_HOME, MAV_CMD.MAV_CMD_DO_SET_ROI,
            MAV_CMD.MAV_CMD_DO_LAND_START, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, MAV_CMD.MAV_CMD_NAV_VTOL_LAND);

    /** Item 0 of a vehicle whose home is not set. */
    static final MissionItem UNSET_HOME = new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL,
            0, 0, 0, 0, 0, 0, 0, true);

    private StoredItems() {
    }

    /**
     * The file a vehicle holding {@code sent} reads back over FTP ({@link MissionFtpFile}): each item
     * as it keeps it, and for a mission its home in place of item 0.
     *
     * @param home the vehicle's home, for a mission: null for a vehicle whose home is not set (its
     *             item 0 all zeros, AP_AHRS's home before it is set); unused for a fence or rally points
     */
    public static byte[] file(MissionType type, List<MissionItem> sent, Position home, boolean plane) {
        List<MissionItem> held = new ArrayList<>(sent.size());
        for (MissionItem i : sent) {
            held.add(switch (type) {
                case MISSION -> i.seq() != 0 ? missionItem(i, plane) : home == null ? UNSET_HOME : home(home);
                case FENCE -> fenceItem(i);
                case RALLY -> rallyItem(i);
            });
        }
        return MissionFtpFile.encode(type, held);
    }

    /**
     * Home as AP_Mission gives it for item 0: a NAV_WAYPOINT at the vehicle's home, its height above
     * mean sea level in the whole centimetres ArduPilot keeps (HOME_POSITION reports them in mm).
     */
    public static MissionItem home(Position home) {
        int centimetres = (int) Math.round(home.hae() * 100);
        return new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL, 0, 0, 0, 0,
                MissionItem.degE7(home.latitudeDegrees()), MissionItem.degE7(home.longitudeDegrees()), centimetres * 0.01f, true);
    }

    /** A fence item as a download reports it. */
    public static MissionItem fenceItem(MissionItem i) {
        float p1 = i.command() == MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT ? 0 : i.param1();
        return new MissionItem(i.seq(), i.command(), MAV_FRAME.MAV_FRAME_GLOBAL, p1, 0, 0, 0, i.x(), i.y(), 0, false);
    }

    /** A rally point as a download reports it. */
    public static MissionItem rallyItem(MissionItem i) {
        return new MissionItem(i.seq(), i.command(), MissionItem.altitudeReference(i.frame()), 0, 0, 0, 0, i.x(), i.y(),
                (short) i.z(), false);
    }

    /** A mission item as a download reports it, for any command ArduPilot accepts. */
    public static MissionItem missionItem(MissionItem i, boolean plane) {
        float p1 = 0;
        float p2 = 0;
        float p3 = 0;
        float p4 = 0;
        switch (i.command()) {
            case MAV_CMD.MAV_CMD_NAV_WAYPOINT -> {
                if (plane) {
                    p2 = Math.min(255, u16(i.param2()));
                    p3 = Math.min(255, u16(i.param3()));
                } else {
                    p1 = u16(i.param1());
                }
            }
            case MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM -> p3 = signed(u16(Math.abs(i.param3())), i.param3() < 0);
            case MAV_CMD.MAV_CMD_NAV_LOITER_TURNS -> {
                // turns in the low byte (fewer than one: times 256), the radius in the high byte (over 255 m: a tenth)
                boolean fraction = i.param1() > 0 && i.param1() < 1;
                int stored = u16(Math.min(255, fraction ? i.param1() * 256 : i.param1()));
                float radius = Math.abs(i.param3());
                stored |= (radius <= 255 ? u8(radius) : u8(Math.min(255, radius * 0.1f))) << 8;
                p1 = fraction ? (stored & 0xff) / 256f : stored & 0xff;
                p3 = signed(stored >> 8 & 0xff, i.param3() < 0) * (radius <= 255 ? 1 : 10);
                p4 = i.param4() > 0 ? 1 : 0;
            }
            case MAV_CMD.MAV_CMD_NAV_LOITER_TIME -> {
                p1 = u16(i.param1());
                p3 = i.param3() < 0 ? -1 : 1;
                p4 = i.param4() > 0 ? 1 : 0;
            }
            // the yaw direction is kept only if param4 is a number; 1 (clockwise) by default
            case MAV_CMD.MAV_CMD_NAV_LAND -> {
                p1 = u16(i.param1());
                p4 = i.param4() <= -Math.ulp(1f) ? -1 : 1;
            }
            case MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT -> {
                p2 = signed(u16(Math.abs(i.param2())), i.param2() < 0);
                p4 = i.param4() > 0 ? 1 : 0;
            }
            case MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_NAV_CONTINUE_AND_CHANGE_ALT, MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT,
                    MAV_CMD.MAV_CMD_DO_SET_HOME, MAV_CMD.MAV_CMD_DO_SET_ROI, MAV_CMD.MAV_CMD_DO_SET_ROI_NONE,
                    MAV_CMD.MAV_CMD_DO_PARACHUTE, MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE -> p1 = u16(i.param1());
            case MAV_CMD.MAV_CMD_NAV_DELAY -> {
                p1 = i.param1();
                p2 = (byte) (int) i.param2();
                p3 = (byte) (int) i.param3();
                p4 = (byte) (int) i.param4();
            }
            case MAV_CMD.MAV_CMD_CONDITION_DELAY, MAV_CMD.MAV_CMD_CONDITION_DISTANCE -> p1 = i.param1();
            // a VTOL landing keeps its options (NAV_VTOL_LAND_OPTIONS), a transition its target state; a VTOL take-off nothing
            case MAV_CMD.MAV_CMD_NAV_VTOL_LAND -> p1 = u16(i.param1());
            case MAV_CMD.MAV_CMD_DO_VTOL_TRANSITION -> p1 = u8(i.param1());
            case MAV_CMD.MAV_CMD_CONDITION_YAW -> {
                p1 = i.param1();
                p2 = i.param2();
                p3 = (byte) (int) i.param3();
                p4 = u8(i.param4());
            }
            case MAV_CMD.MAV_CMD_DO_JUMP -> {
                p1 = u16(i.param1());
                p2 = (short) (int) i.param2();
            }
            case MAV_CMD.MAV_CMD_DO_CHANGE_SPEED -> {
                p1 = u8(i.param1());
                p2 = i.param2();
                p3 = i.param3();
            }
            case MAV_CMD.MAV_CMD_DO_SET_RELAY, MAV_CMD.MAV_CMD_DO_GRIPPER -> {
                p1 = u8(i.param1());
                p2 = u8(i.param2());
            }
            case MAV_CMD.MAV_CMD_DO_REPEAT_RELAY -> {
                p1 = u8(i.param1());
                p2 = (short) (int) i.param2();
                p3 = i.param3();
            }
            case MAV_CMD.MAV_CMD_DO_SET_SERVO -> {
                p1 = u8(i.param1());
                p2 = u16(i.param2());
            }
            case MAV_CMD.MAV_CMD_DO_REPEAT_SERVO -> {
                p1 = u8(i.param1());
                p2 = u16(i.param2());
                p3 = (short) (int) i.param3();
                p4 = i.param4();
            }
            case MAV_CMD.MAV_CMD_DO_DIGICAM_CONFIGURE -> {
                return new MissionItem(i.seq(), i.command(), MAV_FRAME.MAV_FRAME_GLOBAL, u8(i.param1()), u16(i.param2()),
                        u8(i.param3()), u16(i.param4()), i.x() & 0xff, i.y() & 0xff, i.z(), true);
            }
            case MAV_CMD.MAV_CMD_DO_DIGICAM_CONTROL -> {
                return new MissionItem(i.seq(), i.command(), MAV_FRAME.MAV_FRAME_GLOBAL, u8(i.param1()), u8(i.param2()),
                        (byte) (int) i.param3(), u8(i.param4()), i.x() & 0xff, i.y() & 0xff, 0, true);
            }
            case MAV_CMD.MAV_CMD_DO_MOUNT_CONTROL -> {
                return new MissionItem(i.seq(), i.command(), MAV_FRAME.MAV_FRAME_GLOBAL, i.param1(), i.param2(), i.param3(), 0,
                        0, 0, MAV_MOUNT_MODE.MAV_MOUNT_MODE_MAVLINK_TARGETING, true);
            }
            case MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST -> {
                p1 = i.param1();
                p3 = u8(i.param3());
            }
            case MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE -> {
                p1 = u8(i.param1());
                p2 = i.param2();
                p3 = u16(i.param3());
                p4 = u16(i.param4());
            }
            case MAV_CMD.MAV_CMD_VIDEO_START_CAPTURE, MAV_CMD.MAV_CMD_VIDEO_STOP_CAPTURE -> p1 = u8(i.param1());
            // NAV_RETURN_TO_LAUNCH and DO_LAND_START keep nothing but their location, if any
            default -> {
            }
        }
        if (!POSITIONAL.contains(i.command())) {
            return new MissionItem(i.seq(), i.command(), MAV_FRAME.MAV_FRAME_GLOBAL, p1, p2, p3, p4, 0, 0, 0, true);
        }
        int reference = MissionItem.altitudeReference(i.frame());
        int frame = reference == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT || reference == MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT
                ? reference : MAV_FRAME.MAV_FRAME_GLOBAL;
        int centimetres = (int) (i.z() * 100.0f);
        return new MissionItem(i.seq(), i.command(), frame, p1, p2, p3, p4, i.x(), i.y(), centimetres * 0.01f, true);
    }

    /** A magnitude kept apart from its sign (loiter_ccw), negated as a float: -0 when it is 0. */
    private static float signed(int magnitude, boolean negative) {
        return negative ? -(float) magnitude : magnitude;
    }

    private static int u8(float f) {
        return (int) f & 0xff;
    }

    private static int u16(float f) {
        return (int) f & 0xffff;
    }
}
