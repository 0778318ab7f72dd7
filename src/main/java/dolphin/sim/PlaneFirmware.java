package dolphin.sim;

import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MAV_PARAM_TYPE;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MAV_STATE;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.enums.PLANE_MODE;
import dolphin.core.Position;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;

/**
 * ArduPlane as SITL runs it with plane.parm: 20 m/s cruise (at once: its acceleration is not
 * simulated), climbing at 5 m/s and sinking at 3,
 * WP_RADIUS 55 m (or the item's param2), WP_LOITER_RAD 60 m; it arms in any mode and flies a
 * mission as soon as it is armed in AUTO; it holds by circling; at the end of its mission it
 * switches itself to RTL and circles home. Streams at 1 Hz from boot. Its landing is the copter's,
 * simplified. A QuadPlane is one too ({@link QuadPlaneFirmware}).
 */
class PlaneFirmware implements Firmware {

    private static final Performance PERFORMANCE = new Performance(20, 5, 3, 55, 60, 0, 20);
    /** NAVL1_DAMPING's default. */
    private static final double L1_DAMPING = 0.75;
    /** ArduPlane's modes that navigate by themselves (Mode::does_auto_navigation), and AUTO. */
    private static final Set<Integer> AUTO_NAVIGATION = Set.of(PLANE_MODE.PLANE_MODE_AUTO, PLANE_MODE.PLANE_MODE_GUIDED,
            PLANE_MODE.PLANE_MODE_CIRCLE, PLANE_MODE.PLANE_MODE_LOITER, PLANE_MODE.PLANE_MODE_RTL, PLANE_MODE.PLANE_MODE_TAKEOFF,
            PLANE_MODE.PLANE_MODE_THERMAL, PLANE_MODE.PLANE_MODE_AUTOLAND);
    private static final List<FirmwareParam> PARAMS = List.of(new FirmwareParam("Q_ENABLE", 0, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT8));

    @Override
    public int mavType() {
        return MAV_TYPE.MAV_TYPE_FIXED_WING;
    }

    @Override
    public VehicleFamily family() {
        return VehicleFamily.PLANE;
    }

    @Override
    public double defaultStreamHz() {
        return 1;
    }

    @Override
    public Performance performance() {
        return PERFORMANCE;
    }

    /**
     * Q_ENABLE 0, which tells a plane from a QuadPlane; the other Q_ parameters, hidden while it is 0
     * (AP_PARAM_FLAG_ENABLE), get no answer.
     */
    @Override
    public List<FirmwareParam> params() {
        return PARAMS;
    }

    /** Every mode but those whose does_auto_navigation() is true, and AUTO. */
    @Override
    public boolean resetsLandedMissionIn(int mode) {
        return !AUTO_NAVIGATION.contains(mode);
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

    /** AP_Arming_Plane::disarm resets the mission unless in AUTO. */
    @Override
    public boolean resetsMissionOnDisarm(boolean inAuto) {
        return !inAuto;
    }

    /** A plane never stops: it flies on past every waypoint. */
    @Override
    public boolean passesOn(MissionItem next) {
        return true;
    }

    /**
     * Plane::verify_nav_wp: p2, or AP_L1_Control::turn_distance: the lesser of WP_RADIUS and the L1
     * distance at cruise, in proportion to a turn of less than 90 degrees, so that a waypoint straight
     * ahead is flown over.
     */
    @Override
    public double acceptanceRadius(MissionItem waypoint, double turn) {
        if (waypoint.param2() > 0) {
            return waypoint.param2();
        }
        double distance = Math.min(performance().waypointRadius(), L1_DAMPING * l1Period() * performance().speed() / Math.PI);
        return distance * Math.min(1, turn / (Math.PI / 2));
    }

    /** NAVL1_PERIOD: models/plane.parm's. */
    double l1Period() {
        return 15;
    }

    /** Within the radius horizontally; the height is only flown towards. */
    @Override
    public boolean reach(Craft craft, Position target, double radius, double endSpeed, double dt) {
        craft.fly(target, endSpeed, radius, dt);
        return craft.distanceTo(target) <= radius;
    }

    @Override
    public Manoeuvre takeoff(Craft craft, double altitude) {
        return new Takeoff(craft, altitude, craft::climbAhead, 0);
    }

    @Override
    public Manoeuvre holdAt(Craft craft, Position at) {
        return new Orbit(this, craft, at, performance().loiterRadius(), Double.POSITIVE_INFINITY);
    }

    @Override
    public Manoeuvre landing(Craft craft, Position over) {
        return new Landing(craft, over);
    }

    @Override
    public Manoeuvre returnHome(Craft craft, Position home, boolean asMissionItem) {
        return new ReturnAndHold(this, craft, home, asMissionItem);
    }

    /** Plane::verify_nav_wp. */
    @Override
    public Optional<String> arrivalText(int seq, double distance, double holdSeconds) {
        return Optional.of(String.format(Locale.ROOT, "Reached waypoint #%d dist %dm", seq, Math.round(distance)));
    }

    @Override
    public Optional<String> passedText(int seq, double distance) {
        return Optional.of(String.format(Locale.ROOT, "Passed waypoint #%d dist %dm", seq, Math.round(distance)));
    }

    @Override
    public Optional<String> completionText(MissionItem item) {
        return Optional.empty();
    }

    /** Plane's mission end: RTL, announced, if it is still flying. */
    @Override
    public void missionComplete(MissionFlight.Body body) {
        if (body.armed()) {
            body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Mission complete, changing mode to RTL");
            body.switchMode(PLANE_MODE.PLANE_MODE_RTL);
        }
    }

    @Override
    public int landedState(boolean onGround, int manoeuvreState) {
        return onGround ? MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND : manoeuvreState;
    }

    @Override
    public int systemStatus(boolean armed, boolean onGround) {
        return onGround ? MAV_STATE.MAV_STATE_STANDBY : MAV_STATE.MAV_STATE_ACTIVE;
    }

    @Override
    public Failures failures() {
        return FaultTable.PLANE;
    }
}
