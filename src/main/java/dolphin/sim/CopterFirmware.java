package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MAV_STATE;
import com.MAVLink.enums.MAV_TYPE;
import dolphin.core.Position;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.MissionItem;
import java.util.Optional;
import java.util.Set;

/**
 * ArduCopter as SITL runs it with copter.parm: WPNAV_SPD 10 m/s, WPNAV_SPD_UP 2.5, WPNAV_SPD_DN 1.5,
 * WPNAV_ACC 2.5 m/s² (its jerk limit not simulated); waypoints reached within about a metre (SITL: 0.6
 * to 1.5 m), whatever their param2, flown past without stopping when the next nav item is another
 * point to fly to, else stopped on; a vertical take-off {@link #SPOOL_UP} seconds after it may take
 * off, hovering to hold, landing and RTL with LAND's descent; no streams until asked. A traditional
 * helicopter is one too ({@link HeliFirmware}).
 */
class CopterFirmware implements Firmware {

    /**
     * How long SITL's copter stays on the ground once it may take off: its motors spool up and its
     * throttle ramps up until it lifts (3.3 to 4 s in the recordings, docs/mavlink.md).
     */
    static final double SPOOL_UP = 3.5;

    private static final Performance PERFORMANCE = new Performance(10, 2.5, 1.5, 1, 10, 2.5, 2.5);
    private static final Set<Integer> FLOWN_ON_TO = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT,
            MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, MAV_CMD.MAV_CMD_NAV_LOITER_TIME);

    @Override
    public int mavType() {
        return MAV_TYPE.MAV_TYPE_QUADROTOR;
    }

    @Override
    public VehicleFamily family() {
        return VehicleFamily.COPTER;
    }

    @Override
    public double defaultStreamHz() {
        return 0;
    }

    @Override
    public Performance performance() {
        return PERFORMANCE;
    }

    /** ModeAuto::allows_arming: AUTO is not armable without AUTO_OPTIONS. */
    @Override
    public Optional<String> armRefusal(int mode, MissionView mission) {
        return mode == autoMode() ? Optional.of("Arm: AUTO mode not armable") : Optional.empty();
    }

    @Override
    public String armedText() {
        return "Arming motors";
    }

    @Override
    public String disarmedText() {
        return "Disarming motors";
    }

    /** Without MISSION_START (or throttle) the copter is not auto_armed and does not take off. */
    @Override
    public boolean waitsForMissionStart() {
        return true;
    }

    /** ModeAuto::init: "Auto: Missing Takeoff Cmd". */
    @Override
    public boolean autoNeedsTakeoff() {
        return true;
    }

    /** AP_Arming_Copter::disarm resets the mission in any mode; AP_Mission, still running in AUTO, starts it over. */
    @Override
    public boolean resetsMissionOnDisarm(boolean inAuto) {
        return true;
    }

    /** ModeAuto::set_next_wp: on to another waypoint or a loiter; it stops before a landing, a take-off, RTL or LOITER_TURNS. */
    @Override
    public boolean passesOn(MissionItem next) {
        return FLOWN_ON_TO.contains(next.command());
    }

    @Override
    public double acceptanceRadius(MissionItem waypoint, double turn) {
        return PERFORMANCE.waypointRadius();
    }

    /** A copter must be at the point's height too: reached within the radius in three dimensions. */
    @Override
    public boolean reach(Craft craft, Position target, double radius, double endSpeed, double dt) {
        craft.fly(target, endSpeed, radius, dt);
        double[] ned = craft.position().displacementTo(target);
        return Math.sqrt(ned[0] * ned[0] + ned[1] * ned[1] + ned[2] * ned[2]) <= radius && (endSpeed > 0 || craft.stopped());
    }

    @Override
    public Manoeuvre takeoff(Craft craft, double altitude) {
        return new Takeoff(craft, altitude, craft::climbTo, SPOOL_UP);
    }

    /** Hovers over the point, braking to it if it came in moving. */
    @Override
    public Manoeuvre holdAt(Craft craft, Position at) {
        return dt -> {
            craft.fly(at, dt);
            return false;
        };
    }

    @Override
    public Manoeuvre landing(Craft craft, Position over) {
        return new Landing(craft, over);
    }

    @Override
    public Manoeuvre returnHome(Craft craft, Position home, boolean asMissionItem) {
        return new ReturnAndLand(craft, home);
    }

    @Override
    public Optional<String> arrivalText(int seq, double distance, double holdSeconds) {
        return Optional.empty();
    }

    /** ModeAuto::verify_nav_wp and verify_loiter_time, once the hold is over. */
    @Override
    public Optional<String> completionText(MissionItem item) {
        return Optional.of("Reached command #" + item.seq());
    }

    /** ModeAuto::exit_mission: hovers where it is in AUTO; on the ground it disarms. */
    @Override
    public void missionComplete(MissionFlight.Body body) {
        if (body.armed() && body.craft().contact()) {
            body.disarm();
        }
    }

    /** GCS_MAVLINK_Copter::landed_state. */
    @Override
    public int landedState(boolean onGround, int manoeuvreState) {
        return onGround ? MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND : manoeuvreState;
    }

    /** STANDBY on the ground, armed or not, ACTIVE once it flies, as SITL's heartbeats show. */
    @Override
    public int systemStatus(boolean armed, boolean onGround) {
        return onGround ? MAV_STATE.MAV_STATE_STANDBY : MAV_STATE.MAV_STATE_ACTIVE;
    }

    @Override
    public Failures failures() {
        return FaultTable.COPTER;
    }
}
