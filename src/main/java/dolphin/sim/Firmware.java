package dolphin.sim;

import com.MAVLink.enums.MAV_RESULT;
import com.MAVLink.enums.MAV_VTOL_STATE;
import dolphin.core.Position;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.ModeTable;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;

/**
 * What the simulated ArduCopter, ArduPlane, ArduRover and ArduSub do differently: identity, modes and
 * default streams; speeds and radii; the arming and mode rules; which mission items it starts; how
 * each one takes off, reaches a point, holds, lands, returns home and ends a mission; what it
 * reports of being on the ground; and what its faults do ({@link Failures}). {@link SimVehicle} and
 * {@link MissionFlight} ask their vehicle's firmware and never test its kind. Each vehicle runs one of
 * its own ({@link VehicleKind#newFirmware}), which may keep what ArduPilot keeps beside the mission:
 * a QuadPlane's transition, a helicopter's motor interlock.
 */
interface Firmware {

    /** MAV_TYPE in the heartbeat. */
    int mavType();

    VehicleFamily family();

    /** Its modes: their table, the one it boots in, its mission's, its RTL and its LAND. */
    default SimModes modeSet() {
        return SimModes.of(Autopilot.ARDUPILOT, family());
    }

    default ModeTable modes() {
        return modeSet().table();
    }

    /** What it is called, e.g. "ArduCopter". */
    default String label() {
        return modeSet().autopilot().label(family());
    }

    /** The custom mode it boots in. */
    default int bootMode() {
        return modeSet().boot();
    }

    default int autoMode() {
        return modeSet().auto();
    }

    /** Its RTL mode, which a fence breach and MAV_CMD_NAV_RETURN_TO_LAUNCH switch to; empty for ArduSub, which has none. */
    default OptionalInt rtlMode() {
        return modeSet().rtl();
    }

    /** The mode MAV_CMD_NAV_LAND switches to; empty when the firmware does not take that command. */
    default OptionalInt landMode() {
        return modeSet().land();
    }

    /**
     * The STATUSTEXT (WARNING) with which it refuses to enter {@code mode}, given whether it has a
     * position estimate and a mission, whether it is armed and the clock time (nanoseconds); empty if
     * it enters it (as far as the firmware's mode rules go).
     */
    default Optional<String> modeRefusal(int mode, boolean located, boolean missionPresent, boolean armed, long now) {
        return Optional.empty();
    }

    /** The parameters it answers PARAM_REQUEST_READ with, in index order; empty: it answers none. */
    default List<FirmwareParam> params() {
        return List.of();
    }

    /**
     * MAV_CMD_DO_AUX_FUNCTION: RC option {@code function} to switch position {@code position} (0 LOW,
     * 1 MIDDLE, 2 HIGH) at clock time {@code now}; its MAV_RESULT. UNSUPPORTED: no function is simulated.
     */
    default int auxFunction(int function, int position, boolean armed, long now) {
        return MAV_RESULT.MAV_RESULT_UNSUPPORTED;
    }

    /**
     * Whether a change to {@code mode} while disarmed on the ground resets a mission that landed
     * ("In landing sequence: mission reset", Plane::set_mode): ArduPlane's modes without auto navigation.
     */
    default boolean resetsLandedMissionIn(int mode) {
        return false;
    }

    /** Rebooted: what it keeps of its own goes back to how it boots (a helicopter's interlock follows its RC8 again). */
    default void rebooted() {
    }

    /** EXTENDED_SYS_STATE's vtol_state in {@code mode}; UNDEFINED but on a QuadPlane (GCS_MAVLINK_Plane::vtol_state). */
    default int vtolState(int mode, boolean onGround) {
        return MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED;
    }

    /** The rate of the streams it sends before anyone asks, per second; 0 for none. */
    double defaultStreamHz();

    Performance performance();

    /** The STATUSTEXT with which it refuses to arm in {@code mode} with {@code mission}; empty if it arms there. */
    Optional<String> armRefusal(int mode, MissionView mission);

    /** Whether it refuses to arm without a position estimate ("PreArm: Need Position Estimate", repeated while disarmed). */
    default boolean needsPositionToArm() {
        return true;
    }

    /** Whether a disarm (unless forced) is refused while it flies ("Disarm: vehicle is flying"). */
    default boolean disarmsOnlyLanded() {
        return true;
    }

    /** Said on arming. */
    String armedText();

    /** Said on disarming. */
    String disarmedText();

    /** Said on disarming by itself once landed. */
    default String landedDisarmText() {
        return disarmedText();
    }

    /** Armed on the ground and not flying a mission, it disarms itself after this many seconds; 0: never. */
    default double preflightDisarmSeconds() {
        return 0;
    }

    /** The STATUSTEXT (INFO) when the mission starts an item, as AP_Mission says it ("Mission: 3 WP"); empty: none. */
    default Optional<String> startText(MissionItem item) {
        return Optional.of("Mission: " + item.seq() + " " + CommandNames.of(item.command()));
    }

    /** Armed on the ground in AUTO, it waits for MAV_CMD_MISSION_START before it starts the mission. */
    boolean waitsForMissionStart();

    /** Armed on the ground, it enters AUTO only when the first nav item is a take-off. */
    boolean autoNeedsTakeoff();

    /**
     * Whether disarming resets its mission to the first item (AP_Mission::reset: no current item,
     * the DO_JUMP counts at zero, the mission's state kept), given whether it is in AUTO.
     */
    boolean resetsMissionOnDisarm(boolean inAuto);

    /**
     * Disarmed in AUTO, it runs its mission through at once without moving: each nav item complete
     * as soon as it starts (ArduSub). Otherwise a disarmed vehicle's mission waits at its nav item.
     */
    default boolean runsMissionDisarmed() {
        return false;
    }

    /**
     * What it does instead of starting a nav item (its frame, its command): the refusal's texts, and
     * whether the mission then skips to the next item or stops; empty when it starts the item.
     */
    default Optional<NavRefusal> navRefusal(MissionItem item) {
        return Optional.empty();
    }

    /**
     * The nav command it flies {@code command} as: a QuadPlane flies NAV_VTOL_TAKEOFF as NAV_TAKEOFF
     * and NAV_VTOL_LAND as NAV_LAND; other firmwares fly each command as itself.
     */
    default int fliesAs(int command) {
        return command;
    }

    /**
     * The height (above the ellipsoid) a take-off item climbs to, given its altitude {@code itemAltitude}
     * in its frame; a QuadPlane climbs the item's altitude above where it is.
     */
    default double takeoffAltitude(MissionItem item, double itemAltitude, Craft craft) {
        return itemAltitude;
    }

    /** How close a NAV_WAYPOINT counts as reached, {@code turn} radians (0 to pi) the turn onto the leg after it. */
    double acceptanceRadius(MissionItem waypoint, double turn);

    /**
     * Moves the craft towards {@code target} for {@code dt} seconds, to come within {@code radius} of
     * it at {@code endSpeed} (0: to stop on it); true once within {@code radius}, and stopped if it is
     * to stop there.
     */
    boolean reach(Craft craft, Position target, double radius, double endSpeed, double dt);

    /**
     * Whether it flies on past a NAV_WAYPOINT that has no hold time towards {@code next}, the nav
     * item after it, instead of stopping on the waypoint.
     */
    boolean passesOn(MissionItem next);

    Manoeuvre takeoff(Craft craft, double altitude);

    /** Staying at a point for as long as asked. */
    Manoeuvre holdAt(Craft craft, Position at);

    /** NAV_LAND at {@code over} (null: where it is), and the LAND mode. */
    Manoeuvre landing(Craft craft, Position over);

    /** A mission's NAV_LAND at {@code over} (null: where it is): the LAND mode's landing unless the firmware's differs. */
    default Manoeuvre missionLanding(Craft craft, Position over) {
        return landing(craft, over);
    }

    /**
     * Whether a NAV_LAND is reported reached as its descent begins and left armed when it lands, for
     * the mission's end to disarm (a PX4 multicopter); else it is reached once landed and disarmed.
     */
    default boolean reachesLandingOnDescent() {
        return false;
    }

    /**
     * Whether a NAV_LAND is complete once it has landed and disarmed; a QuadPlane's mission stays at
     * its landing, ACTIVE (QuadPlane::check_land_complete).
     */
    default boolean completesLanding() {
        return true;
    }

    /** Whether {@code mode}, neither AUTO nor RTL nor LAND, moves the vehicle by itself (a QuadPlane's QRTL, QLOITER). */
    default boolean fliesIn(int mode) {
        return false;
    }

    /** The manoeuvre of such a mode, from where the craft is; one that ends on the ground ends with a disarm. */
    default Manoeuvre modeFlight(int mode, Craft craft, Position home) {
        throw new IllegalArgumentException("mode " + mode + " does not fly by itself");
    }

    /** What it does when the manoeuvre of its LAND mode is over: landed, it disarms. */
    default void landModeDone(MissionFlight.Body body) {
        body.disarm();
    }

    /** RTL, as a mode or as NAV_RETURN_TO_LAUNCH in a mission. */
    Manoeuvre returnHome(Craft craft, Position home, boolean asMissionItem);

    /** The STATUSTEXT on arriving at waypoint {@code seq}, {@code distance} metres from it. */
    Optional<String> arrivalText(int seq, double distance, double holdSeconds);

    /**
     * Plane::verify_nav_wp's other way to a waypoint: past the line through it square to the leg, not
     * yet within its acceptance distance; the STATUSTEXT that says so. Empty: this firmware does not
     * take a waypoint that way.
     */
    default Optional<String> passedText(int seq, double distance) {
        return Optional.empty();
    }

    /** The STATUSTEXT when a waypoint (or LOITER_TIME) is complete. */
    Optional<String> completionText(MissionItem item);

    /** What the vehicle does when its mission is over. */
    void missionComplete(MissionFlight.Body body);

    /** EXTENDED_SYS_STATE's landed_state, given whether it is on the ground and its manoeuvre's state. */
    int landedState(boolean onGround, int manoeuvreState);

    /** The heartbeat's system_status, without a failsafe on (which makes it MAV_STATE_CRITICAL). */
    int systemStatus(boolean armed, boolean onGround);

    /** What it does when things go wrong: its row of {@link FaultTable}. */
    Failures failures();
}
