package dolphin.sim;

import com.MAVLink.enums.MAV_PARAM_TYPE;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MAV_STATE;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.enums.MAV_VTOL_STATE;
import dolphin.core.Position;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Optional;

/**
 * A family's flight model (the copter's, the plane's, the QuadPlane's) flown by PX4, as its SITL with
 * SIH did (docs/mavlink.md, "Simulated PX4 vehicles"): PX4's modes, booting in AUTO.LOITER; it arms
 * in any mode and flies its mission as soon as it is armed in AUTO.MISSION, a multicopter with no
 * take-off item needed; no text per item; a multicopter lands as PX4's ({@link Px4Landing}); a landing
 * detected, then disarmed COM_DISARM_LAND ({@link #DISARM_LAND}) seconds later, a multicopter's
 * mission landing at once, by the mission's end, its landing item reported reached as the descent
 * began (px4-copter-fenced-hop); a multicopter armed on the ground disarms itself after
 * COM_DISARM_PRFLT ({@link #DISARM_PREFLIGHT}) seconds; a finished mission stays in AUTO.MISSION,
 * holding where it ended unless it landed; a multicopter's AUTO.RTL climbs to RTL_RETURN_ALT
 * ({@link #RTL_RETURN_ALT}) above home, returns and lands. A standard VTOL (the QuadPlane's model) says
 * so in its heartbeat and its VTOL state. Everything else is the family's.
 */
final class Px4Firmware implements Firmware {

    /** COM_DISARM_LAND: seconds on the ground after a landing before it disarms. */
    static final double DISARM_LAND = 2;
    /** COM_DISARM_PRFLT on a multicopter: armed on the ground, it disarms itself after this many seconds. */
    static final double DISARM_PREFLIGHT = 10;
    /** NAV_ACC_RAD, metres. */
    static final double NAV_ACC_RAD = 10;
    /** RTL_RETURN_ALT, metres above home. */
    static final double RTL_RETURN_ALT = 60;

    private static final List<FirmwareParam> PLANE_PARAMS = List.of(
            new FirmwareParam("FW_LND_ANG", 5, MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32));

    private final Firmware base;

    Px4Firmware(Firmware base) {
        this.base = base;
    }

    @Override
    public SimModes modeSet() {
        return SimModes.of(Autopilot.PX4, family());
    }

    /** A standard VTOL is MAV_TYPE_VTOL_FIXEDROTOR, RESERVED2 in our bindings. */
    @Override
    public int mavType() {
        return family() == VehicleFamily.VTOL ? MAV_TYPE.MAV_TYPE_VTOL_RESERVED2 : base.mavType();
    }

    @Override
    public VehicleFamily family() {
        return base.family();
    }

    /** A plane's FW_LND_ANG (its default), which the runtime reads to check a landing's approach as PX4 does. */
    @Override
    public List<FirmwareParam> params() {
        return family() == VehicleFamily.PLANE ? PLANE_PARAMS : List.of();
    }

    @Override
    public void rebooted() {
        base.rebooted();
    }

    /** The VTOL's state in flight as its model has it; on the ground a multicopter (VTOL_STATE_MC). */
    @Override
    public int vtolState(int mode, boolean onGround) {
        if (family() != VehicleFamily.VTOL) {
            return MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED;
        }
        return onGround ? MAV_VTOL_STATE.MAV_VTOL_STATE_MC : base.vtolState(mode, false);
    }

    /**
     * As the family's ArduPilot vehicle: PX4 streams much from boot, which the simulation leaves out, so
     * that a fleet of hundreds stays light; the runtime asks for what it needs with SET_MESSAGE_INTERVAL.
     */
    @Override
    public double defaultStreamHz() {
        return base.defaultStreamHz();
    }

    @Override
    public Performance performance() {
        return base.performance();
    }

    @Override
    public Optional<String> armRefusal(int mode, MissionView mission) {
        return Optional.empty();
    }

    @Override
    public boolean needsPositionToArm() {
        return base.needsPositionToArm();
    }

    @Override
    public String armedText() {
        return "Armed by external command";
    }

    @Override
    public String disarmedText() {
        return "Disarmed by external command";
    }

    @Override
    public String landedDisarmText() {
        return "Disarmed by landing";
    }

    @Override
    public double preflightDisarmSeconds() {
        return family() == VehicleFamily.COPTER ? DISARM_PREFLIGHT : 0;
    }

    /** Armed in AUTO.MISSION, it flies. */
    @Override
    public boolean waitsForMissionStart() {
        return false;
    }

    /** MIS_TKO_LAND_REQ 0 on a multicopter; a fixed wing's requirement is a landing, checked for feasibility. */
    @Override
    public boolean autoNeedsTakeoff() {
        return false;
    }

    /** A landed mission stays COMPLETE, to be started again from its first item. */
    @Override
    public boolean resetsMissionOnDisarm(boolean inAuto) {
        return false;
    }

    @Override
    public Optional<String> startText(MissionItem item) {
        return Optional.empty();
    }

    @Override
    public int fliesAs(int command) {
        return base.fliesAs(command);
    }

    /** At least NAV_ACC_RAD: PX4 takes a waypoint within it, with no line past the waypoint to cross instead. */
    @Override
    public double acceptanceRadius(MissionItem waypoint, double turn) {
        return Math.max(NAV_ACC_RAD, base.acceptanceRadius(waypoint, turn));
    }

    @Override
    public boolean reach(Craft craft, Position target, double radius, double endSpeed, double dt) {
        return base.reach(craft, target, radius, endSpeed, dt);
    }

    @Override
    public boolean passesOn(MissionItem next) {
        return base.passesOn(next);
    }

    @Override
    public Manoeuvre takeoff(Craft craft, double altitude) {
        return base.takeoff(craft, altitude);
    }

    @Override
    public Manoeuvre holdAt(Craft craft, Position at) {
        return base.holdAt(craft, at);
    }

    /** Landed, it disarms COM_DISARM_LAND later. */
    @Override
    public Manoeuvre landing(Craft craft, Position over) {
        return new LandedWait(craft, descent(craft, over), DISARM_LAND);
    }

    /** A multicopter's: landed, the mission is over at once, and its end disarms it. */
    @Override
    public Manoeuvre missionLanding(Craft craft, Position over) {
        return family() == VehicleFamily.COPTER ? new LandedWait(craft, descent(craft, over), 0) : landing(craft, over);
    }

    /** A multicopter's landing item is reached as its descent begins, over the landing point (MissionBase's move to it done). */
    @Override
    public boolean reachesLandingOnDescent() {
        return family() == VehicleFamily.COPTER;
    }

    private Manoeuvre descent(Craft craft, Position over) {
        return family() == VehicleFamily.COPTER ? new Px4Landing(craft, over) : base.landing(craft, over);
    }

    /** A multicopter's RTL lands (RTL_LAND_DELAY 0); a fixed wing's circles home, as the family's. */
    @Override
    public Manoeuvre returnHome(Craft craft, Position home, boolean asMissionItem) {
        return family() == VehicleFamily.COPTER ? new LandedWait(craft, new ReturnAndLand(craft, home, RTL_RETURN_ALT, 0), DISARM_LAND)
                : base.returnHome(craft, home, asMissionItem);
    }

    @Override
    public Optional<String> arrivalText(int seq, double distance, double holdSeconds) {
        return Optional.empty();
    }

    @Override
    public Optional<String> completionText(MissionItem item) {
        return Optional.empty();
    }

    /** mission_base.cpp setEndOfMissionItems: in the air it holds, on the ground it is done; the mode stays. */
    @Override
    public void missionComplete(MissionFlight.Body body) {
        if (body.armed() && !body.craft().contact()) {
            body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Mission finished, loitering");
        } else {
            body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Mission finished, landed");
            if (body.armed()) {
                body.disarm();
            }
        }
    }

    @Override
    public int landedState(boolean onGround, int manoeuvreState) {
        return base.landedState(onGround, manoeuvreState);
    }

    @Override
    public int systemStatus(boolean armed, boolean onGround) {
        return armed ? MAV_STATE.MAV_STATE_ACTIVE : MAV_STATE.MAV_STATE_STANDBY;
    }

    /** The family's, but a pilot taking over holds in AUTO.LOITER. */
    @Override
    public Failures failures() {
        Failures f = base.failures();
        return new Failures(f.motors(), f.powerLoss(), f.ekfFailsafe(), bootMode(), f.internalError());
    }

    /** A manoeuvre that ends on the ground, over {@code wait} seconds after PX4's land detector said so. */
    private static final class LandedWait implements Manoeuvre {
        private final Craft craft;
        private final Manoeuvre landing;
        private final double wait;
        private double onGround = -1;

        LandedWait(Craft craft, Manoeuvre landing, double wait) {
            this.craft = craft;
            this.landing = landing;
            this.wait = wait;
        }

        @Override
        public boolean step(double dt) {
            if (onGround < 0) {
                if (!landing.step(dt)) {
                    return false;
                }
                onGround = 0;
                craft.say("Landing detected");
                return wait == 0;
            }
            onGround += dt;
            return onGround >= wait;
        }

        @Override
        public int landedState() {
            return landing.landedState();
        }

        @Override
        public boolean endsOnGround() {
            return landing.endsOnGround();
        }
    }
}
