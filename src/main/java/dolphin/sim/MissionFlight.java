package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_current;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MISSION_STATE;
import dolphin.core.Position;
import dolphin.mission.model.MissionItem;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

/**
 * How a simulated vehicle flies its stored mission in AUTO, and RTL and LAND, on the fleet's tick in
 * clock time, by AP_Mission's rules: each item started says so ("Mission: 3 WP"); a nav item runs
 * until it completes; the DO items after it run when it does, in the same loop, so their
 * MISSION_ITEM_REACHED coalesces with its; CONDITION_DELAY runs beside the next nav item; DO_JUMP
 * loops. How the vehicle takes off, reaches a point, holds, lands, returns and ends the mission, and
 * whether it waits for MISSION_START or starts over when disarmed, is its {@link Firmware}'s.
 */
final class MissionFlight {

    /** A copter armed on the ground in AUTO without MISSION_START disarms after DISARM_DELAY seconds. */
    static final double DISARM_DELAY = 10;
    /** DO_JUMP's repeat count meaning for ever (AP_MISSION_JUMP_REPEAT_FOREVER). */
    static final int FOREVER = -1;

    private static final Set<Integer> CAMERA = Set.of(MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE,
            MAV_CMD.MAV_CMD_DO_DIGICAM_CONTROL, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST);

    /**
     * DO items AP_Mission::verify_command completes itself, without the vehicle's verify: they are
     * never reported reached (SITL sends no MISSION_ITEM_REACHED for IMAGE_START_CAPTURE).
     */
    private static final Set<Integer> VERIFIED_BY_MISSION = Set.of(MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE,
            MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE, MAV_CMD.MAV_CMD_DO_DIGICAM_CONTROL, MAV_CMD.MAV_CMD_DO_DIGICAM_CONFIGURE,
            MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, MAV_CMD.MAV_CMD_DO_SET_SERVO, MAV_CMD.MAV_CMD_DO_SET_RELAY,
            MAV_CMD.MAV_CMD_DO_REPEAT_SERVO, MAV_CMD.MAV_CMD_DO_REPEAT_RELAY, MAV_CMD.MAV_CMD_DO_GRIPPER,
            MAV_CMD.MAV_CMD_DO_PARACHUTE);

    /** What the flight needs from its vehicle. */
    interface Body {
        Craft craft();

        Position home();

        boolean armed();

        int mode();

        /** A mode change of the vehicle's own, announced at once. */
        void switchMode(int mode);

        /** Disarms, saying so; the flight hears of it through {@link #disarmed()}. */
        void disarm();

        void text(int severity, String text);

        void reached(int seq);

        /** Ends one of ArduPilot's loops: what waits to be sent goes out. */
        void flush();

        void send(MAVLinkMessage m);
    }

    private enum Phase { APPROACH, HOLD }

    private final Firmware firmware;
    private final MissionStore store;
    private final Body body;
    /** The next item to run. */
    private int current = 1;
    /** The nav item MISSION_CURRENT names: the one started last, 0 before any. */
    private int navIndex;
    private boolean started;
    private boolean complete;
    private boolean autoArmed;
    private boolean restartDue;
    private double groundSeconds;
    private int cameraCommands;
    // the nav item under way
    private int active = -1;
    private Phase phase;
    private double timer;
    private Manoeuvre manoeuvre;
    // RTL and LAND modes
    private Manoeuvre modeManoeuvre;
    // a CONDITION_DELAY running beside the nav item
    private int conditionSeq = -1;
    private double conditionLeft;
    /** Jumps made by each DO_JUMP (by seq) since the mission started. */
    private final Map<Integer, Integer> jumpsRun = new HashMap<>();
    /** The last MISSION_CURRENT announced (seq/total/state); a change is sent at once, as ArduPilot does. */
    private String lastCurrent = "0/0/" + MISSION_STATE.MISSION_STATE_NO_MISSION;

    MissionFlight(Firmware firmware, MissionStore store, Body body) {
        this.firmware = firmware;
        this.store = store;
        this.body = body;
    }

    int cameraCommands() {
        return cameraCommands;
    }

    /** The nav item MISSION_CURRENT reports. */
    int current() {
        return navIndex;
    }

    /** MISSION_STATE of the stored mission. */
    int state() {
        if (store.count() <= 1) {
            return MISSION_STATE.MISSION_STATE_NO_MISSION;
        }
        if (complete) {
            return MISSION_STATE.MISSION_STATE_COMPLETE;
        }
        if (!started) {
            return MISSION_STATE.MISSION_STATE_NOT_STARTED;
        }
        return body.mode() == firmware.autoMode() ? MISSION_STATE.MISSION_STATE_ACTIVE : MISSION_STATE.MISSION_STATE_PAUSED;
    }

    /** Armed and running a mission in AUTO: ArduPilot then refuses MISSION_CLEAR_ALL. */
    boolean flyingMission() {
        return body.armed() && body.mode() == firmware.autoMode() && started && !complete;
    }

    /** ModeAuto::init: armed and landed, a copter enters AUTO only for a mission that starts with a take-off. */
    boolean autoAllowed() {
        if (!firmware.autoNeedsTakeoff() || !body.armed() || !body.craft().onGround()) {
            return true;
        }
        for (int i = 1; i < store.count(); i++) {
            MissionItem item = store.get(i);
            if (nav(item.command())) {
                return item.command() == MAV_CMD.MAV_CMD_NAV_TAKEOFF;
            }
        }
        return false;
    }

    /** EXTENDED_SYS_STATE's view of the manoeuvre under way: TAKEOFF, LANDING or IN_AIR. */
    int manoeuvreState() {
        Manoeuvre m = body.mode() == firmware.autoMode() ? (active >= 0 ? manoeuvre : null) : modeManoeuvre;
        return m == null || !body.armed() ? MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR : m.landedState();
    }

    /** Called after every mode change. */
    void modeChanged(int from, int to) {
        if (to == from) {
            return;
        }
        modeManoeuvre = null;
        active = -1;
        manoeuvre = null;
        groundSeconds = 0;
        if (to == firmware.autoMode()) {
            if (complete || current >= store.count()) {
                restart();
            }
            body.craft().resetSpeed();
        }
    }

    /** MAV_CMD_MISSION_START: the copter's auto_armed; the mission (re)starts if it had ended. */
    void missionStart() {
        if (complete) {
            restart();
        }
        if (body.armed()) {
            autoArmed = true;
        }
    }

    /** MISSION_SET_CURRENT, MAV_CMD_DO_SET_MISSION_CURRENT: false if there is no such item. */
    boolean setCurrent(int seq) {
        if (seq < 1 || seq >= store.count()) {
            return false;
        }
        current = seq;
        navIndex = seq;
        complete = false;
        active = -1;
        manoeuvre = null;
        announceCurrent(true);
        return true;
    }

    /** The stored mission changed: outside a running mission, start again from the first item. */
    void missionChanged() {
        if (!flyingMission()) {
            restart();
        }
    }

    /** From the first item again, with every DO_JUMP's count at zero (AP_Mission::start). */
    private void restart() {
        current = 1;
        navIndex = 0;
        started = false;
        complete = false;
        active = -1;
        manoeuvre = null;
        jumpsRun.clear();
    }

    void disarmed() {
        autoArmed = false;
        groundSeconds = 0;
        if (firmware.restartsMissionOnDisarm() && body.mode() == firmware.autoMode() && started && !complete) {
            restartDue = true;
        }
    }

    void tick(double dt) {
        if (body.armed()) {
            int mode = body.mode();
            if (mode == firmware.autoMode()) {
                auto(dt);
            } else if (mode == firmware.rtlMode()) {
                modeStep(dt, () -> firmware.returnHome(body.craft(), body.home(), false));
            } else if (firmware.landMode().isPresent() && mode == firmware.landMode().getAsInt()) {
                modeStep(dt, () -> firmware.landing(body.craft(), null));
            }
        }
        if (restartDue) {
            restartDue = false;
            body.flush();
            restartAfterDisarm();
        }
        body.flush();
        announceCurrent(false);
    }

    /** MISSION_CURRENT: seq is the nav item started last (kept once complete); total excludes home. */
    MAVLinkMessage missionCurrent() {
        msg_mission_current c = new msg_mission_current();
        int state = state();
        c.seq = state == MISSION_STATE.MISSION_STATE_NO_MISSION ? 0 : Math.min(navIndex, store.count() - 1);
        c.total = Math.max(0, store.count() - 1);
        c.mission_state = (short) state;
        c.mission_mode = (short) (body.mode() == firmware.autoMode() ? 1 : 0);
        return c;
    }

    private void announceCurrent(boolean always) {
        msg_mission_current c = (msg_mission_current) missionCurrent();
        String key = c.seq + "/" + c.total + "/" + c.mission_state;
        if (always || !key.equals(lastCurrent)) {
            lastCurrent = key;
            body.send(c);
        }
    }

    /** RTL or LAND mode: a manoeuvre that, if it ends on the ground, ends with a disarm. */
    private void modeStep(double dt, Supplier<Manoeuvre> make) {
        if (modeManoeuvre == null) {
            modeManoeuvre = make.get();
        }
        if (modeManoeuvre.step(dt) && modeManoeuvre.endsOnGround()) {
            body.disarm();
        }
    }

    private void auto(double dt) {
        if (firmware.waitsForMissionStart() && !autoArmed) {
            if (!body.craft().onGround()) {
                autoArmed = true;
            } else {
                groundSeconds += dt;
                if (groundSeconds >= DISARM_DELAY) {
                    body.disarm();
                }
                return;
            }
        }
        groundSeconds = 0;
        if (complete || store.count() <= 1) {
            return; // it stays where the mission left it
        }
        started = true;
        conditionStep(dt);
        for (int guard = 0; guard < store.count() + 1; guard++) {
            if (current >= store.count()) {
                finish();
                return;
            }
            MissionItem item = store.get(current);
            if (item.command() == MAV_CMD.MAV_CMD_DO_JUMP) {
                if (!jump(item)) {
                    finish();
                    return;
                }
                continue;
            }
            if (!nav(item.command())) {
                if (startDo(item)) {
                    body.reached(item.seq());
                }
                current++;
                continue;
            }
            if (active != current) {
                begin(item);
            }
            if (!step(item, dt)) {
                return;
            }
            body.reached(current);
            current++;
            active = -1;
            manoeuvre = null;
            dt = 0;
            if (!body.armed()) {
                // landed and disarmed by the item: the mission goes on only through its DO items
                while (current < store.count() && !nav(store.get(current).command())
                        && store.get(current).command() != MAV_CMD.MAV_CMD_DO_JUMP) {
                    if (startDo(store.get(current))) {
                        body.reached(current);
                    }
                    current++;
                }
                if (current >= store.count()) {
                    finish();
                }
                return;
            }
        }
    }

    private void finish() {
        complete = true;
        active = -1;
        manoeuvre = null;
        firmware.missionComplete(body);
    }

    /**
     * Disarmed in AUTO in the middle of its mission, ArduCopter starts the mission over at once: in
     * one loop the DO items before the first nav item start again, in the next they are reported
     * reached and the first nav item becomes current, the mission ACTIVE though the copter is
     * disarmed. That item runs when the copter is armed and started again.
     */
    private void restartAfterDisarm() {
        restart();
        started = true;
        List<Integer> toReport = new ArrayList<>();
        while (current < store.count() && !nav(store.get(current).command())
                && store.get(current).command() != MAV_CMD.MAV_CMD_DO_JUMP) {
            if (startDo(store.get(current))) {
                toReport.add(current);
            }
            current++;
        }
        body.flush();
        toReport.forEach(body::reached);
        if (current < store.count() && nav(store.get(current).command())) {
            navIndex = current;
            announceStart(store.get(current));
        }
    }

    /**
     * AP_Mission::get_next_cmd: a DO_JUMP sends the mission back to item p1, p2 times (-1: for ever),
     * then lets it go on; it is never "reached". A target outside the mission (0, or past the end) ends
     * the mission there. As AP_Mission counts, the first jump is silent and later ones say
     * "Mission: 4 Jump 2/3".
     */
    private boolean jump(MissionItem item) {
        int target = (int) item.param1();
        if (target <= 0 || target >= store.count()) {
            return false;
        }
        int times = (int) item.param2();
        int run = jumpsRun.getOrDefault(item.seq(), 0);
        if (times == FOREVER) {
            current = target;
        } else if (run < times) {
            jumpsRun.put(item.seq(), run + 1);
            if (run > 0) {
                body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Mission: " + item.seq() + " Jump " + (run + 1) + "/" + times);
            }
            current = target;
        } else {
            current++;
        }
        return true;
    }

    /** Starts a DO item; true if it is complete at once and reported reached. */
    private boolean startDo(MissionItem item) {
        announceStart(item);
        int cmd = item.command();
        if (cmd == MAV_CMD.MAV_CMD_DO_CHANGE_SPEED && item.param2() > 0) {
            body.craft().speed(item.param2());
        } else if (CAMERA.contains(cmd)) {
            cameraCommands++;
        } else if (cmd == MAV_CMD.MAV_CMD_CONDITION_DELAY) {
            conditionSeq = item.seq();
            conditionLeft = Math.max(0, item.param1());
            return false; // reached when the delay has passed
        }
        return !VERIFIED_BY_MISSION.contains(cmd);
    }

    private void conditionStep(double dt) {
        if (conditionSeq >= 0) {
            conditionLeft -= dt;
            if (conditionLeft <= 0) {
                body.reached(conditionSeq);
                conditionSeq = -1;
            }
        }
    }

    private void announceStart(MissionItem item) {
        body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Mission: " + item.seq() + " " + CommandNames.of(item.command()));
    }

    private void begin(MissionItem item) {
        active = current;
        navIndex = current;
        phase = Phase.APPROACH;
        timer = 0;
        modeManoeuvre = null;
        announceStart(item);
        Craft craft = body.craft();
        manoeuvre = switch (item.command()) {
            case MAV_CMD.MAV_CMD_NAV_TAKEOFF -> firmware.takeoff(craft, altitude(item));
            case MAV_CMD.MAV_CMD_NAV_LAND -> firmware.landing(craft, item.x() == 0 && item.y() == 0 ? null
                    : Position.fromDegrees(item.x() * 1e-7, item.y() * 1e-7, craft.position().hae()));
            case MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH -> firmware.returnHome(craft, body.home(), true);
            default -> null;
        };
    }

    /** One tick of the current nav item; true when it is complete. */
    private boolean step(MissionItem item, double dt) {
        return switch (item.command()) {
            case MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH -> manoeuvre.step(dt);
            case MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_TIME ->
                    waypoint(item, dt, item.param1());
            case MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM -> waypoint(item, dt, Double.POSITIVE_INFINITY);
            case MAV_CMD.MAV_CMD_NAV_LOITER_TURNS -> turns(item, dt);
            case MAV_CMD.MAV_CMD_NAV_DELAY -> {
                timer += dt;
                yield timer >= Math.max(0, item.param1());
            }
            case MAV_CMD.MAV_CMD_NAV_LAND -> land(dt);
            default -> {
                body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Skipping invalid cmd #" + item.seq());
                yield true;
            }
        };
    }

    /** Goes to the item's position, then holds there for {@code holdSeconds}. */
    private boolean waypoint(MissionItem item, double dt, double holdSeconds) {
        Position t = target(item);
        boolean plainWaypoint = item.command() != MAV_CMD.MAV_CMD_NAV_LOITER_TIME
                && item.command() != MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM;
        if (phase == Phase.APPROACH) {
            double radius = item.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT ? firmware.acceptanceRadius(item)
                    : firmware.performance().waypointRadius();
            if (!firmware.reach(body.craft(), t, radius, dt)) {
                return false;
            }
            if (plainWaypoint) {
                firmware.arrivalText(item.seq(), body.craft().distanceTo(t), holdSeconds)
                        .ifPresent(s -> body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, s));
            }
            phase = Phase.HOLD;
            manoeuvre = firmware.holdAt(body.craft(), t);
            dt = 0;
        }
        manoeuvre.step(dt);
        timer += dt;
        if (timer < Math.max(0, holdSeconds)) {
            return false;
        }
        firmware.completionText(item.seq()).ifPresent(s -> body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, s));
        return true;
    }

    /** LOITER_TURNS: to the circle's north point, then p1 turns of radius |p3| (0: the firmware's). */
    private boolean turns(MissionItem item, double dt) {
        Performance performance = firmware.performance();
        double r = Math.abs(item.param3()) > 0 ? Math.abs(item.param3()) : performance.loiterRadius();
        Position centre = target(item);
        if (phase == Phase.APPROACH) {
            if (!firmware.reach(body.craft(), Orbit.entry(centre, r), performance.precisionRadius(), dt)) {
                return false;
            }
            phase = Phase.HOLD;
            manoeuvre = new Orbit(firmware, body.craft(), centre, r, item.param1());
            dt = 0;
        }
        return manoeuvre.step(dt);
    }

    /**
     * NAV_LAND: complete once landed and disarmed; but a firmware that starts its mission over when
     * disarmed never completes it (ArduCopter: no MISSION_ITEM_REACHED for the landing).
     */
    private boolean land(double dt) {
        if (!manoeuvre.step(dt)) {
            return false;
        }
        if (manoeuvre.endsOnGround() && body.armed()) {
            body.disarm();
        }
        return !restartDue;
    }

    /** The item's position; lat = lon = 0 means here; z relative to home unless the frame is global. */
    private Position target(MissionItem item) {
        Position p = body.craft().position();
        double lat = item.x() == 0 && item.y() == 0 ? p.latitudeDegrees() : item.x() * 1e-7;
        double lon = item.x() == 0 && item.y() == 0 ? p.longitudeDegrees() : item.y() * 1e-7;
        return Position.fromDegrees(lat, lon, altitude(item));
    }

    private double altitude(MissionItem item) {
        return MissionCheck.relative(item.frame()) ? body.home().hae() + item.z() : item.z();
    }

    /** NAV commands are those below MAV_CMD_NAV_LAST (95), as AP_Mission::is_nav_cmd says. */
    static boolean nav(int command) {
        return command < MAV_CMD.MAV_CMD_NAV_LAST;
    }
}
