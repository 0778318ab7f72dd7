package dolphin.mission.file

import dolphin.mission.model.MissionItem
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.core.Position

/** Mission items for the file format specs: awkward values on purpose. */
final class MissionFileFixtures {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    private MissionFileFixtures() {
    }

    /** A mission as Mission.items gives it: home at 0, then take-off, waypoints, a DO command, loiter, land. */
    static List<MissionItem> mission() {
        [
                MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, Position.fromDegrees(40.444233, -7.375234, 1200), 15, 0, 0, Float.NaN),
                MissionItem.at(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME.displace(100, 200, -100), 0, 50, 0, Float.NaN),
                MissionItem.command(3, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 0, 12.5f, -1, 0),
                MissionItem.at(4, MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, Position.fromDegrees(-33.8688197, 151.2092955, 55.25), 3, 0, 0.1f, 0),
                MissionItem.command(5, MAV_CMD.MAV_CMD_NAV_DELAY, 30, -1, -1, -1),
                MissionItem.at(6, MAV_CMD.MAV_CMD_NAV_LAND, HOME, 0, 0, 0, Float.NaN),
        ]
    }

    /** Items with extreme and tricky values: degE7 at the limits, -0, tiny and huge floats, autocontinue off. */
    static List<MissionItem> extremes() {
        [
                new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 0, 0, 0, 0, 900000000, -1800000000, -431.7f, true),
                new MissionItem(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, -0.0f, 1e-7f, 3.4028235e38f, Float.MIN_VALUE, -900000000, 1800000000, 8848.86f, false),
                new MissionItem(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, (1.0f / 3) as float, (2.0f / 3) as float, 123456.79f, -7.0e-5f, 1, -1, 0.3f, true),
                new MissionItem(3, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT, 0, 0, -15, Float.NaN, 123456789, -98765432, Float.NaN, true),
                new MissionItem(4, MAV_CMD.MAV_CMD_DO_SET_SERVO, MAV_FRAME.MAV_FRAME_MISSION, 9, 1900, 0, 0, 0, 0, 0, true),
        ]
    }

    /** Seeded random items in every frame a file can carry, for round trips. */
    static List<MissionItem> random(long seed, int count) {
        def r = new Random(seed)
        def frames = [MAV_FRAME.MAV_FRAME_GLOBAL_INT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                      MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT, MAV_FRAME.MAV_FRAME_MISSION]
        Closure<Float> param = {
            switch (r.nextInt(6)) {
                case 0: return Float.NaN
                case 1: return 0f
                case 2: return (float) r.nextInt(100)
                case 3: return Float.intBitsToFloat(r.nextInt()) // any bit pattern; NaN payloads become the canonical NaN
                default: return (float) ((r.nextDouble() - 0.5) * 2000)
            }
        }
        Closure<Integer> lat = { r.nextInt(1_800_000_001) - 900_000_000 }
        Closure<Integer> lon = { (int) (Math.floorMod(r.nextLong(), 3_600_000_001L) - 1_800_000_000L) }
        // Item 0 is the home item as Mission.items makes it (a .plan keeps only its position).
        [new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 0, 0, 0, 0, lat(), lon(),
                (float) (r.nextDouble() * 3000), true)] +
                (1..<count).collect { int seq ->
                    float p1 = param(), p2 = param(), p3 = param(), p4 = param(), z = param()
                    new MissionItem(seq, 16 + r.nextInt(200), frames[r.nextInt(frames.size())],
                            canonical(p1), canonical(p2), canonical(p3), canonical(p4), lat(), lon(),
                            canonical(z), r.nextInt(5) > 0)
                }
    }

    /** Infinities are not kept by .plan (JSON); NaN is kept. Round trips use finite values or NaN. */
    private static float canonical(float f) {
        Float.isInfinite(f) ? 1f : f
    }
}
