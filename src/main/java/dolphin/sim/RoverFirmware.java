package dolphin.sim;

import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MAV_STATE;
import dolphin.core.Position;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.MissionItem;
import java.util.Optional;

/**
 * ArduRover as SITL runs it with rover.parm: it drives on the ground at WP_SPEED 5 m/s, gathering
 * speed and braking at ATC_ACCEL_MAX 1 m/s² (ArduRover's default), heights ignored, a waypoint
 * reached within WP_RADIUS 3 m (the item's param2 does not count) and driven past towards the next
 * nav item, the last one stopped on; it arms in any mode and drives a
 * mission as soon as it is armed in AUTO; a take-off is done at once and a landing is a waypoint;
 * at the end of a mission it stops and stays in AUTO (MIS_DONE_BEHAVE 0, hold). Like a copter, no
 * streams until asked. It does not report a landed state (ArduRover has none: UNDEFINED). The same
 * firmware drives a boat (ArduRover with FRAME_CLASS 2, SITL's motorboat), which differs only in the
 * MAV_TYPE of its heartbeat.
 */
final class RoverFirmware implements Firmware {

    private static final Performance PERFORMANCE = new Performance(5, 0, 0, 3, 2, 1, 2.5);

    private final int mavType;

    /** ArduRover announcing itself as {@code mavType}: MAV_TYPE_GROUND_ROVER, or MAV_TYPE_SURFACE_BOAT for a boat. */
    RoverFirmware(int mavType) {
        this.mavType = mavType;
    }

    @Override
    public int mavType() {
        return mavType;
    }

    @Override
    public VehicleFamily family() {
        return VehicleFamily.ROVER;
    }

    @Override
    public double defaultStreamHz() {
        return 0;
    }

    @Override
    public Performance performance() {
        return PERFORMANCE;
    }

    @Override
    public Optional<String> armRefusal(int mode, MissionView mission) {
        return Optional.empty();
    }

    @Override
    public String armedText() {
        return "Throttle armed";
    }

    @Override
    public String disarmedText() {
        return "Throttle disarmed";
    }

    @Override
    public boolean waitsForMissionStart() {
        return false;
    }

    @Override
    public boolean autoNeedsTakeoff() {
        return false;
    }

    /** AP_Arming_Rover::disarm resets the mission unless in AUTO. */
    @Override
    public boolean resetsMissionOnDisarm(boolean inAuto) {
        return !inAuto;
    }

    /** ModeAuto::do_nav_wp: on to whatever nav item comes next. */
    @Override
    public boolean passesOn(MissionItem next) {
        return true;
    }

    /** AR_WPNav takes WP_RADIUS whatever the item's param2 says (a plane's acceptance radius, 50 m in our waypoints). */
    @Override
    public double acceptanceRadius(MissionItem waypoint, double turn) {
        return PERFORMANCE.waypointRadius();
    }

    @Override
    public boolean reach(Craft craft, Position target, double radius, double endSpeed, double dt) {
        craft.drive(target, endSpeed, radius, dt);
        return craft.distanceTo(target) <= radius && (endSpeed > 0 || craft.stopped());
    }

    @Override
    public Manoeuvre takeoff(Craft craft, double altitude) {
        return Manoeuvre.DONE;
    }

    /** Stands at the point, braking to it if it came in moving. */
    @Override
    public Manoeuvre holdAt(Craft craft, Position at) {
        return dt -> {
            craft.drive(at, dt);
            return false;
        };
    }

    /** A landing point is driven to like a waypoint; LAND without a position is done where it is. */
    @Override
    public Manoeuvre landing(Craft craft, Position over) {
        return over == null ? Manoeuvre.DONE : dt -> reach(craft, over, PERFORMANCE.waypointRadius(), 0, dt);
    }

    @Override
    public Manoeuvre returnHome(Craft craft, Position home, boolean asMissionItem) {
        return new ReturnAndHold(this, craft, home, asMissionItem);
    }

    /** ModeAuto::verify_nav_wp. */
    @Override
    public Optional<String> arrivalText(int seq, double distance, double holdSeconds) {
        return Optional.of(holdSeconds > 0 ? "Reached waypoint #" + seq + ". Loiter for " + Math.round(holdSeconds) + " seconds"
                : "Reached waypoint #" + seq);
    }

    @Override
    public Optional<String> completionText(MissionItem item) {
        return Optional.empty();
    }

    /** ModeAuto::exit_mission with MIS_DONE_BEHAVE 0: says so and stops, in AUTO. */
    @Override
    public void missionComplete(MissionFlight.Body body) {
        body.text(MAV_SEVERITY.MAV_SEVERITY_NOTICE, "Mission Complete");
    }

    @Override
    public int landedState(boolean onGround, int manoeuvreState) {
        return MAV_LANDED_STATE.MAV_LANDED_STATE_UNDEFINED;
    }

    /** A rover is ACTIVE while armed. */
    @Override
    public int systemStatus(boolean armed, boolean onGround) {
        return armed ? MAV_STATE.MAV_STATE_ACTIVE : MAV_STATE.MAV_STATE_STANDBY;
    }

    @Override
    public Failures failures() {
        return FaultTable.ROVER;
    }
}
