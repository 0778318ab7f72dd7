package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MAV_STATE;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.enums.SUB_MODE;
import dolphin.core.Position;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.MissionItem;
import dolphin.mission.transfer.StoredItems;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * ArduSub as SITL runs it with sub.parm and {@code --model vectored} (docs/decisions.md, "ArduSub
 * behaviour"): under water at about 0.9 m/s horizontally and 0.4 m/s up or down, never above the
 * surface; it stops on each waypoint, reached within a metre in three dimensions. It arms in any
 * mode without pre-arm complaints; AUTO, GUIDED, POSHOLD and CIRCLE need a position estimate, AUTO a
 * mission too. Each nav item's altitude frame is checked before it starts (Sub::start_command):
 * depth is a negative height above home, and an item in any other frame is refused, skipped without
 * being reached. Disarmed in AUTO it runs its mission through at once; at the end of a mission it
 * holds where it is, armed in AUTO. NAV_LAND is surfacing, and so is its SURFACE mode, which ends in
 * ALT_HOLD at the surface. It has no RTL mode. Streams at 2 Hz from boot (ArduSub's default rates).
 */
final class SubFirmware implements Firmware {

    private static final Performance PERFORMANCE = new Performance(0.9, 0.4, 0.4, 1, 2, 0.5, 0.5);

    /** Modes whose requires_GPS() is true (ArduSub/mode.h), with the names its refusal gives them. */
    private static final Map<Integer, String> NEED_POSITION = Map.of(SUB_MODE.SUB_MODE_AUTO, "Auto",
            SUB_MODE.SUB_MODE_GUIDED, "Guided", SUB_MODE.SUB_MODE_POSHOLD, "Position Hold", SUB_MODE.SUB_MODE_CIRCLE, "Circle");

    /** The nav commands Sub::start_command handles; any other is "Ignoring command N". */
    private static final Set<Integer> HANDLED = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LAND,
            MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, MAV_CMD.MAV_CMD_NAV_LOITER_TURNS,
            MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_GUIDED_ENABLE, MAV_CMD.MAV_CMD_NAV_DELAY);

    private static final Set<Integer> ABOVE_HOME = Set.of(MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT,
            MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT);
    private static final Set<Integer> ABOVE_TERRAIN = Set.of(MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT,
            MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT);

    /**
     * A terrain item in SITL: sub.parm's simulated rangefinder gives no terrain there, so the waypoint
     * cannot be set and the terrain failsafe stops the mission (ModeAuto::auto_wp_start,
     * auto_terrain_recover_start). SITL disarms 10 s later, which the simulator leaves out.
     */
    private static final NavRefusal NO_TERRAIN = new NavRefusal(
            List.of("Terrain data (rangefinder) not available", "Attempting auto failsafe recovery"), true);

    @Override
    public int mavType() {
        return MAV_TYPE.MAV_TYPE_SUBMARINE;
    }

    @Override
    public VehicleFamily family() {
        return VehicleFamily.SUB;
    }

    /** Sub::set_mode: a mode that needs a position, then ModeAuto::init's mission. */
    @Override
    public Optional<String> modeRefusal(int mode, boolean located, boolean missionPresent, boolean armed, long now) {
        if (NEED_POSITION.containsKey(mode) && !located) {
            return Optional.of("Mode change failed: " + NEED_POSITION.get(mode) + " requires position");
        }
        if (mode == autoMode() && !missionPresent) {
            return Optional.of("Flight mode change failed Auto");
        }
        return Optional.empty();
    }

    /** ArduSub's default stream rates: EXT_STAT 2 Hz (SYS_STATUS, MISSION_CURRENT), POSITION 3, EXTRA3 3; 2 for all here. */
    @Override
    public double defaultStreamHz() {
        return 2;
    }

    @Override
    public Performance performance() {
        return PERFORMANCE;
    }

    @Override
    public Optional<String> armRefusal(int mode, MissionView mission) {
        return Optional.empty();
    }

    /** SITL's sub armed 3 s after boot, long before its EKF had a position. */
    @Override
    public boolean needsPositionToArm() {
        return false;
    }

    /** A sub is disarmed wherever it is, as the recording's was at 10 m depth. */
    @Override
    public boolean disarmsOnlyLanded() {
        return false;
    }

    @Override
    public String armedText() {
        return "Arming motors";
    }

    @Override
    public String disarmedText() {
        return "Disarming motors";
    }

    @Override
    public boolean waitsForMissionStart() {
        return false;
    }

    @Override
    public boolean autoNeedsTakeoff() {
        return false;
    }

    /** AP_Arming_Sub::disarm resets the mission in any mode. */
    @Override
    public boolean resetsMissionOnDisarm(boolean inAuto) {
        return true;
    }

    @Override
    public boolean runsMissionDisarmed() {
        return true;
    }

    /**
     * Sub::start_command: the altitude frame first, then the command. Depth relative to home must not
     * be above it; a terrain height not below the terrain; any other frame is refused. Commands stored
     * without a location (RTL, NAV_DELAY, GUIDED_ENABLE) have their frame read from their parameters'
     * bytes, which say "absolute" for RTL (as SITL showed) and for whole seconds of delay: refused too.
     */
    @Override
    public Optional<NavRefusal> navRefusal(MissionItem item) {
        int frame = StoredItems.POSITIONAL.contains(item.command()) ? item.frame() : MAV_FRAME.MAV_FRAME_GLOBAL;
        long centimetres = Math.round(item.z() * 100.0);
        if (ABOVE_HOME.contains(frame)) {
            if (centimetres > 0) {
                return Optional.of(NavRefusal.skipped("Alt above home must be negative"));
            }
        } else if (ABOVE_TERRAIN.contains(frame)) {
            if (centimetres < 0) {
                return Optional.of(NavRefusal.skipped("Alt above terrain must be positive"));
            }
            return HANDLED.contains(item.command()) ? Optional.of(NO_TERRAIN) : ignored(item);
        } else {
            return Optional.of(NavRefusal.skipped("Bad alt frame"));
        }
        return HANDLED.contains(item.command()) ? Optional.empty() : ignored(item);
    }

    private static Optional<NavRefusal> ignored(MissionItem item) {
        return Optional.of(NavRefusal.skipped("Ignoring command " + item.command()));
    }

    /** AC_WPNav::set_wp_destination without a next destination: it stops on every waypoint. */
    @Override
    public boolean passesOn(MissionItem next) {
        return false;
    }

    @Override
    public double acceptanceRadius(MissionItem waypoint, double turn) {
        return PERFORMANCE.waypointRadius();
    }

    /** At the point's depth too: reached within the radius in three dimensions, stopped. */
    @Override
    public boolean reach(Craft craft, Position target, double radius, double endSpeed, double dt) {
        craft.dive(target, endSpeed, radius, dt);
        double[] ned = craft.position().displacementTo(target.atHeight(Math.min(target.hae(), craft.ground())));
        return Math.sqrt(ned[0] * ned[0] + ned[1] * ned[1] + ned[2] * ned[2]) <= radius && (endSpeed > 0 || craft.stopped());
    }

    /** Never run: Sub::start_command ignores NAV_TAKEOFF. */
    @Override
    public Manoeuvre takeoff(Craft craft, double altitude) {
        return Manoeuvre.DONE;
    }

    /** Holds position and depth, braking to the point if it came in moving. */
    @Override
    public Manoeuvre holdAt(Craft craft, Position at) {
        return dt -> {
            craft.dive(at, 0, 0, dt);
            return false;
        };
    }

    /**
     * Sub::do_surface and verify_surface: to the point at its depth (none: where it is), then
     * straight up to the surface; over there, as SURFACE mode is once at the surface.
     */
    @Override
    public Manoeuvre landing(Craft craft, Position over) {
        return new Surfacing(this, craft, over);
    }

    /** ModeSurface::run: at the surface it switches to ALT_HOLD, holding depth 0. */
    @Override
    public void landModeDone(MissionFlight.Body body) {
        body.switchMode(SUB_MODE.SUB_MODE_ALT_HOLD);
    }

    /** Never run as a mission item (refused: no location, "Bad alt frame") nor as a mode (it has none): home at the surface. */
    @Override
    public Manoeuvre returnHome(Craft craft, Position home, boolean asMissionItem) {
        return dt -> reach(craft, home.atHeight(craft.ground()), PERFORMANCE.waypointRadius(), 0, dt);
    }

    @Override
    public Optional<String> arrivalText(int seq, double distance, double holdSeconds) {
        return Optional.empty();
    }

    /** Sub::verify_nav_wp says so; verify_loiter_time does not. */
    @Override
    public Optional<String> completionText(MissionItem item) {
        return item.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT ? Optional.of("Reached command #" + item.seq()) : Optional.empty();
    }

    /** Sub::exit_mission: it loiters where it is, in AUTO, armed, without a word. */
    @Override
    public void missionComplete(MissionFlight.Body body) {
        // holding is what a complete mission in AUTO does: the craft stays where the last item left it
    }

    /** SITL's sub reports no landed state (EXTENDED_SYS_STATE landed_state 0). */
    @Override
    public int landedState(boolean onGround, int manoeuvreState) {
        return MAV_LANDED_STATE.MAV_LANDED_STATE_UNDEFINED;
    }

    /** ACTIVE while armed, STANDBY disarmed, as the recording's heartbeats show. */
    @Override
    public int systemStatus(boolean armed, boolean onGround) {
        return armed ? MAV_STATE.MAV_STATE_ACTIVE : MAV_STATE.MAV_STATE_STANDBY;
    }

    @Override
    public Failures failures() {
        return FaultTable.SUB;
    }
}
