package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_current;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MAV_RESULT;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MISSION_STATE;
import dolphin.core.Position;
import dolphin.mission.model.Fence;
import dolphin.mission.model.MissionItem;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.Set;
import java.util.function.Supplier;

/**
 * How a simulated vehicle flies its stored mission in AUTO, and RTL and LAND, on the fleet's tick in
 * clock time, by AP_Mission's rules: each item started says so ("Mission: 3 WP"); a nav item runs
 * until it completes; the DO items after it run when it does, in the same loop, so their
 * MISSION_ITEM_REACHED coalesces with its, and the next nav item starts, to be verified from the next
 * loop on; CONDITION_DELAY runs beside the next nav item; DO_JUMP
 * loops. Where the mission stands and whether it runs is its {@link MissionCursor}. Which nav items
 * the vehicle starts, how it takes off, reaches a point, holds, lands, returns and ends the mission,
 * and whether it waits for MISSION_START, runs its mission disarmed or resets it when disarmed, is
 * its {@link Firmware}'s.
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

        /** The fence the vehicle holds (empty without one). */
        Fence fence();

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

        /** An internal error of the firmware's, reported once a boot (AP_InternalError). */
        void internalError(String text);
    }

    private enum Phase { APPROACH, HOLD }

    private final Firmware firmware;
    private final SimAutopilot autopilot;
    private final MissionStore store;
    private final Body body;
    private final MissionCursor cursor;
    /** Whether the stored mission passed the autopilot's check of it (PX4's feasibility check). */
    private boolean feasible = true;
    /** The stored mission's id, which MISSION_CURRENT names (ItemStore.planId). */
    private long missionId;
    private boolean autoArmed;
    private boolean restartDue;
    private double groundSeconds;
    private int cameraCommands;
    // the nav item under way: AP_Mission runs its own copy of it, whatever an upload writes meanwhile
    private MissionItem active;
    private Phase phase;
    private double timer;
    private Manoeuvre manoeuvre;
    /** Whether the landing item under way descends, reported reached (PX4). */
    private boolean descending;
    private double exitSpeed;
    /** The turn at the active waypoint from the leg to it onto the leg after it, in radians (0 to pi); pi when none follows. */
    private double turn;
    /**
     * Where the leg to the nav item started next begins (Plane::set_next_WP's prev_WP_loc): the
     * waypoint just completed; null, where the vehicle is, after anything else.
     */
    private Position legFrom;
    /** Where the leg to the active nav item began. */
    private Position legStart;
    // RTL and LAND modes
    private Manoeuvre modeManoeuvre;
    // a pause before the mode's manoeuvre moves (ArduCopter's land_with_pause), holding where it began
    private double modePause;
    private Manoeuvre pauseHold;
    // a CONDITION_DELAY running beside the nav item
    private int conditionSeq = -1;
    private double conditionLeft;
    /** The last MISSION_CURRENT sent (seq/total/state/id): a change goes out at the end of the tick. */
    private String lastCurrent = "0/0/" + MISSION_STATE.MISSION_STATE_NO_MISSION + "/0";
    /** MISSION_CURRENT asked for (MSG_CURRENT_WAYPOINT), sent at the end of the tick even if unchanged. */
    private boolean currentDue;

    MissionFlight(Firmware firmware, SimAutopilot autopilot, MissionStore store, Body body) {
        this.firmware = firmware;
        this.autopilot = autopilot;
        this.store = store;
        this.body = body;
        this.cursor = new MissionCursor(store);
    }

    int cameraCommands() {
        return cameraCommands;
    }

    /** The nav item MISSION_CURRENT reports. */
    int current() {
        return cursor.nav();
    }

    /**
     * MISSION_STATE of the stored mission as GCS_MAVLINK::mission_state gives AP_Mission's state:
     * NO_MISSION (also a mission its autopilot found infeasible), or NOT_STARTED (stopped), ACTIVE
     * (running) or COMPLETE; never PAUSED.
     */
    int state() {
        if (store.count() <= 1 || !feasible) {
            return MISSION_STATE.MISSION_STATE_NO_MISSION;
        }
        return switch (cursor.run()) {
            case COMPLETE -> MISSION_STATE.MISSION_STATE_COMPLETE;
            case STOPPED -> MISSION_STATE.MISSION_STATE_NOT_STARTED;
            case RUNNING -> MISSION_STATE.MISSION_STATE_ACTIVE;
        };
    }

    /** Armed with its mission running: ArduPilot then refuses MISSION_CLEAR_ALL (AP_Mission::clear). */
    boolean flyingMission() {
        return body.armed() && cursor.running();
    }

    /**
     * ModeAuto::init: armed and landed, a copter enters AUTO only when the mission, from its current
     * nav item (the first when it has none), goes on with a take-off.
     */
    boolean autoAllowed() {
        if (!firmware.autoNeedsTakeoff() || !body.armed() || !body.craft().onGround()) {
            return true;
        }
        for (int i = Math.max(1, cursor.nav()); i < store.count(); i++) {
            MissionItem item = store.get(i);
            if (nav(item.command())) {
                return firmware.fliesAs(item.command()) == MAV_CMD.MAV_CMD_NAV_TAKEOFF;
            }
        }
        return false;
    }

    /** EXTENDED_SYS_STATE's view of the manoeuvre under way: TAKEOFF, LANDING or IN_AIR. */
    int manoeuvreState() {
        Manoeuvre m = body.mode() == firmware.autoMode() ? (active != null ? manoeuvre : null) : modeManoeuvre;
        return m == null || !body.armed() ? MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR : m.landedState();
    }

    /** Called after every mode change: leaving AUTO stops the mission, entering it resumes it (AP_Mission::resume). */
    void modeChanged(int from, int to) {
        if (to == from) {
            return;
        }
        modeManoeuvre = null;
        modePause = 0;
        dropActive();
        groundSeconds = 0;
        if (from == firmware.autoMode()) {
            cursor.stop();
        }
        if (!body.armed() && body.craft().onGround() && atLanding() && firmware.resetsLandedMissionIn(to)) {
            body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "In landing sequence: mission reset");
            cursor.reset();
        }
        if (to == firmware.autoMode()) {
            cursor.resume();
            body.craft().resetSpeed();
        }
    }

    /** The mission stands at a landing: AP_Mission's landing sequence, which its arming checks and Plane::set_mode look at. */
    private boolean atLanding() {
        int seq = cursor.nav();
        return seq > 0 && seq < store.count() && firmware.fliesAs(store.get(seq).command()) == MAV_CMD.MAV_CMD_NAV_LAND;
    }

    /** MAV_CMD_MISSION_START: the copter's auto_armed; a mission not running starts or resumes. */
    void missionStart() {
        if (!cursor.running()) {
            cursor.resume();
            dropActive();
        }
        if (body.armed()) {
            autoArmed = true;
        }
    }

    /**
     * MAV_CMD_DO_SET_MISSION_CURRENT (GCS_MAVLINK::handle_command_do_set_mission_current): DENIED for
     * a seq not stored, FAILED when no nav item follows it. With {@code reset} (param2 = 1) the mission
     * is reset, set to the item and resumed, so it runs (MISSION_CURRENT ACTIVE on its nav item) even
     * outside AUTO; without, a mission not running stays NOT_STARTED at that item. MISSION_CURRENT
     * follows at the end of the tick.
     */
    int setCurrentCommand(int seq, boolean reset) {
        if (seq < 0 || seq >= store.count()) {
            return MAV_RESULT.MAV_RESULT_DENIED;
        }
        if (reset) {
            cursor.reset();
        }
        if (!setCurrentCmd(seq)) {
            return MAV_RESULT.MAV_RESULT_FAILED;
        }
        if (reset) {
            cursor.resume();
        }
        sayStarted();
        currentDue = true;
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    /** MISSION_SET_CURRENT (GCS_MAVLINK::handle_mission_set_current): MISSION_CURRENT at once, with the seq asked for. */
    void setCurrentMessage(int seq) {
        if (setCurrentCmd(seq)) {
            sayStarted();
            body.send(missionCurrent(seq));
        }
    }

    /** AP_Mission::set_current_cmd, for a seq stored; a running mission with no nav item after it completes. */
    private boolean setCurrentCmd(int seq) {
        if (seq < 0 || seq >= store.count() || store.count() <= 1) {
            return false;
        }
        boolean running = cursor.running();
        dropActive();
        if (cursor.setCurrent(seq)) {
            return true;
        }
        if (running) {
            finish();
        }
        return false;
    }

    /**
     * Outside AUTO a running mission's items are started where it was set (AP_Mission starts them
     * whatever the mode) and said so; they run when AUTO resumes them. A nav item the firmware refuses
     * is passed over for the next one at once (AP_Mission::advance_current_nav_cmd), or stops the
     * mission; with none left the mission is complete.
     */
    private void sayStarted() {
        if (!cursor.running() || body.mode() == firmware.autoMode()) {
            return;
        }
        int from = Math.min(cursor.next(), cursor.nav());
        while (true) {
            for (int i = from; i <= cursor.nav(); i++) {
                if (store.get(i).command() != MAV_CMD.MAV_CMD_DO_JUMP) {
                    announceStart(store.get(i));
                }
            }
            Optional<NavRefusal> refusal = refusal(store.get(cursor.nav()));
            if (refusal.isEmpty()) {
                return;
            }
            if (refusal.get().stopsMission()) {
                cursor.stop();
                return;
            }
            from = cursor.nav() + 1;
            if (!cursor.setCurrent(from)) {
                finish();
                return;
            }
        }
    }

    /** The firmware's refusal to start a nav item, said: empty when it starts it. */
    private Optional<NavRefusal> refusal(MissionItem navItem) {
        Optional<NavRefusal> refusal = firmware.navRefusal(navItem);
        refusal.ifPresent(r -> r.texts().forEach(t -> body.text(MAV_SEVERITY.MAV_SEVERITY_WARNING, t)));
        return refusal;
    }

    /**
     * The stored mission changed: an upload leaves the mission where it was, running or not (a copter
     * flying it goes on with the nav item under way); a cleared mission has no place. An autopilot that
     * restarts a new mission (PX4) does so unless it flies one. {@code id}: the mission's, as its
     * transfers name it ({@link ItemStore#planId}).
     */
    void missionChanged(long id) {
        missionId = id;
        feasible = autopilot.feasible(store.items(), firmware);
        OptionalInt outside = autopilot.outsideFence(store.items(), body.fence());
        if (outside.isPresent()) {
            feasible = false;
            body.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, "Geofence violation for waypoint " + outside.getAsInt());
        }
        if (store.count() <= 1 || autopilot.restartsOnUpload() && !flyingMission()) {
            cursor.cleared();
            dropActive();
        }
    }

    private void dropActive() {
        active = null;
        manoeuvre = null;
    }

    /**
     * Disarmed: what the firmware resets (AP_Arming_*::disarm). A copter's mission that runs in AUTO
     * starts over at once (restartAfterDisarm); one that runs its mission disarmed (ArduSub) runs it
     * through from the first item in the next tick.
     */
    void disarmed() {
        autoArmed = false;
        groundSeconds = 0;
        boolean inAuto = body.mode() == firmware.autoMode();
        if (!firmware.resetsMissionOnDisarm(inAuto)) {
            return;
        }
        if (inAuto && cursor.running() && !firmware.runsMissionDisarmed()) {
            restartDue = true;
        } else {
            cursor.reset();
            dropActive();
        }
    }

    /**
     * One tick of {@code dt} seconds. While a fault {@code held} the vehicle (a motor lost, a stall),
     * neither its mission nor RTL or LAND moves it or goes on; what it reports still goes out.
     */
    void tick(double dt, boolean held) {
        if (!held) {
            move(dt);
        }
        if (restartDue) {
            restartDue = false;
            body.flush();
            restartAfterDisarm();
        }
        body.flush();
        announceCurrent(currentDue);
        currentDue = false;
    }

    /** AUTO flies the mission, RTL and LAND their manoeuvres. */
    private void move(double dt) {
        int mode = body.mode();
        if (mode == firmware.autoMode()) {
            auto(dt);
        } else if (body.armed()) {
            if (isRtl(mode)) {
                modeStep(dt, () -> firmware.returnHome(body.craft(), body.home(), false), this::disarmIfLanded);
            } else if (isLand(mode)) {
                modeStep(dt, () -> firmware.landing(body.craft(), null), () -> firmware.landModeDone(body));
            } else if (firmware.fliesIn(mode)) {
                modeStep(dt, () -> firmware.modeFlight(mode, body.craft(), body.home()), this::disarmIfLanded);
            }
        }
    }

    /** Whether the flight moves the vehicle in {@code mode}: AUTO, RTL, LAND and the firmware's own flying modes; in any other mode it stays. */
    boolean movesIn(int mode) {
        return mode == firmware.autoMode() || isRtl(mode) || isLand(mode) || firmware.fliesIn(mode);
    }

    private boolean isRtl(int mode) {
        return firmware.rtlMode().isPresent() && mode == firmware.rtlMode().getAsInt();
    }

    private boolean isLand(int mode) {
        return firmware.landMode().isPresent() && mode == firmware.landMode().getAsInt();
    }

    /**
     * Rebooted: AP_Mission starts stopped with no current item (MISSION_CURRENT 0, NOT_STARTED), the
     * stored mission kept; no manoeuvre under way, MISSION_START to be given again.
     */
    void rebooted() {
        cursor.cleared();
        dropActive();
        modeManoeuvre = null;
        modePause = 0;
        conditionSeq = -1;
        autoArmed = false;
        restartDue = false;
        groundSeconds = 0;
    }

    /**
     * MISSION_CURRENT (GCS_MAVLINK::send_mission_current): seq is the current nav item, kept once
     * complete and kept by an upload, even past the new mission's end; total excludes home.
     */
    MAVLinkMessage missionCurrent() {
        return missionCurrent(state() == MISSION_STATE.MISSION_STATE_NO_MISSION ? 0 : cursor.nav());
    }

    private MAVLinkMessage missionCurrent(int seq) {
        boolean paused = cursor.run() == MissionCursor.MissionRun.STOPPED && cursor.nav() > 0;
        return autopilot.missionCurrent(seq, store.count(), state(), paused, body.mode() == firmware.autoMode(), missionId);
    }

    private void announceCurrent(boolean always) {
        msg_mission_current c = (msg_mission_current) missionCurrent();
        String key = c.seq + "/" + c.total + "/" + c.mission_state + "/" + c.mission_id;
        if (always || !key.equals(lastCurrent)) {
            lastCurrent = key;
            body.send(c);
        }
    }

    /**
     * The mode just set holds where the vehicle is for {@code seconds} before its manoeuvre moves it
     * (ArduCopter's set_mode_land_with_pause); meanwhile its landed state is the manoeuvre's (LANDING).
     */
    void pauseMode(double seconds) {
        modePause = seconds;
        pauseHold = firmware.holdAt(body.craft(), body.craft().position());
    }

    /** RTL or LAND mode: a manoeuvre, after the mode's pause if it has one, and what the vehicle does once it is over. */
    private void modeStep(double dt, Supplier<Manoeuvre> make, Runnable done) {
        if (modeManoeuvre == null) {
            modeManoeuvre = make.get();
        }
        if (modePause > 0) {
            modePause -= dt;
            pauseHold.step(dt);
        } else if (modeManoeuvre.step(dt)) {
            done.run();
        }
    }

    /** An RTL that ends on the ground ends with a disarm. */
    private void disarmIfLanded() {
        if (modeManoeuvre != null && modeManoeuvre.endsOnGround()) {
            body.disarm();
        }
    }

    /**
     * One tick of AUTO. Disarmed, or a copter armed on the ground without MISSION_START, it does not
     * move, but its mission runs: the DO items before the nav item run and the nav item starts. Such
     * a copter disarms itself after DISARM_DELAY. A firmware that runs its mission disarmed (ArduSub)
     * completes each nav item as it starts, but for LOITER_UNLIM, which never completes. A nav item
     * the firmware refuses is skipped, or stops the mission.
     */
    private void auto(double dt) {
        if (!cursor.running() || store.count() <= 1) {
            return; // stopped or complete: it stays where the mission left it
        }
        boolean waiting = !body.armed();
        if (!waiting && firmware.waitsForMissionStart() && !autoArmed) {
            if (!body.craft().onGround()) {
                autoArmed = true;
            } else {
                groundSeconds += dt;
                if (groundSeconds >= DISARM_DELAY) {
                    body.disarm();
                    return;
                }
                waiting = true;
            }
        }
        if (!waiting) {
            groundSeconds = 0;
        }
        conditionStep(dt);
        boolean verified = false;
        for (int guard = 0; guard < store.count() + 1; guard++) {
            MissionItem item = item();
            if (item == null) {
                finish();
                return;
            }
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
                cursor.next(item.seq() + 1);
                continue;
            }
            if (active == null && !begin(item)) {
                if (!cursor.running()) {
                    return;
                }
                continue;
            }
            if (verified) {
                return; // AP_Mission::update verifies one nav item a loop: the one it starts waits for the next
            }
            if (!body.armed() && firmware.runsMissionDisarmed()) {
                if (item.command() == MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM) {
                    return;
                }
                body.flush(); // AP_Mission verifies an item in the loop after the one that started it
                firmware.completionText(item).ifPresent(s -> body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, s));
                body.reached(item.seq());
                cursor.next(item.seq() + 1);
                dropActive();
                continue;
            }
            if (waiting || !step(item, dt)) {
                return;
            }
            if (!descending) { // PX4 reported its landing as the descent began
                body.reached(item.seq());
            }
            cursor.next(item.seq() + 1);
            dropActive();
            dt = 0;
            verified = true;
            legFrom = item.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT ? target(item) : null;
            if (!body.armed()) {
                // landed and disarmed by the item: the mission goes on only through its DO items
                while (cursor.next() < store.count() && !nav(store.get(cursor.next()).command())
                        && store.get(cursor.next()).command() != MAV_CMD.MAV_CMD_DO_JUMP) {
                    if (startDo(store.get(cursor.next()))) {
                        body.reached(cursor.next());
                    }
                    cursor.next(cursor.next() + 1);
                }
                if (cursor.next() >= store.count()) {
                    finish();
                }
                return;
            }
        }
    }

    /** The item to run now: the nav item under way as it was started, else the next stored one; null past the end. */
    private MissionItem item() {
        if (active != null && active.seq() == cursor.next()) {
            return active;
        }
        active = null;
        return cursor.next() < store.count() ? store.get(cursor.next()) : null;
    }

    private void finish() {
        cursor.complete();
        dropActive();
        firmware.missionComplete(body);
    }

    /**
     * Disarmed in AUTO in the middle of its mission, ArduCopter starts the mission over at once: in
     * one loop the DO items before the first nav item start again, in the next they are reported
     * reached and the first nav item becomes current, the mission ACTIVE though the copter is
     * disarmed. That item runs when the copter is armed and started again.
     */
    private void restartAfterDisarm() {
        cursor.start();
        dropActive();
        List<Integer> toReport = new ArrayList<>();
        while (cursor.next() < store.count() && !nav(store.get(cursor.next()).command())
                && store.get(cursor.next()).command() != MAV_CMD.MAV_CMD_DO_JUMP) {
            if (startDo(store.get(cursor.next()))) {
                toReport.add(cursor.next());
            }
            cursor.next(cursor.next() + 1);
        }
        body.flush();
        toReport.forEach(body::reached);
        if (cursor.next() < store.count() && nav(store.get(cursor.next()).command())) {
            begin(store.get(cursor.next()));
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
        int run = cursor.jumps(item.seq());
        if (times == FOREVER) {
            cursor.next(target);
        } else if (run < times) {
            cursor.jumped(item.seq());
            if (run > 0) {
                body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Mission: " + item.seq() + " Jump " + (run + 1) + "/" + times);
            }
            cursor.next(target);
        } else {
            cursor.next(item.seq() + 1);
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

    /** "Mission: 3 WP"; a nav item started armed may make the firmware report its internal error (ArduRover's). */
    private void announceStart(MissionItem item) {
        firmware.startText(item).ifPresent(s -> body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, s));
        if (body.armed() && nav(item.command())) {
            firmware.failures().internalError().ifPresent(body::internalError);
        }
    }

    /**
     * Starts a nav item (AP_Mission::start_command): says so, then the firmware starts it or refuses
     * it. False when refused: the mission is then past the item, or stopped at it.
     */
    private boolean begin(MissionItem item) {
        cursor.nav(item.seq());
        announceStart(item);
        Optional<NavRefusal> refusal = refusal(item);
        if (refusal.isPresent()) {
            if (refusal.get().stopsMission()) {
                cursor.stop();
            } else {
                cursor.next(item.seq() + 1);
            }
            return false;
        }
        active = item;
        legStart = legFrom != null ? legFrom : body.craft().position();
        legFrom = null;
        turn = turn(item, legStart);
        exitSpeed = exitSpeed(item, turn(item, body.craft().position()));
        phase = Phase.APPROACH;
        timer = 0;
        descending = false;
        modeManoeuvre = null;
        Craft craft = body.craft();
        manoeuvre = switch (firmware.fliesAs(item.command())) {
            case MAV_CMD.MAV_CMD_NAV_TAKEOFF -> firmware.takeoff(craft, firmware.takeoffAltitude(item, altitude(item), craft));
            case MAV_CMD.MAV_CMD_NAV_LAND -> firmware.missionLanding(craft, item.x() == 0 && item.y() == 0 ? null
                    : Position.fromDegrees(item.x() * 1e-7, item.y() * 1e-7, craft.position().hae()));
            case MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH -> firmware.returnHome(craft, body.home(), true);
            default -> null;
        };
        return true;
    }

    /** One tick of the current nav item; true when it is complete. */
    private boolean step(MissionItem item, double dt) {
        return switch (firmware.fliesAs(item.command())) {
            case MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH -> manoeuvre.step(dt);
            case MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_TIME ->
                    waypoint(item, dt, item.param1());
            case MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM -> waypoint(item, dt, Double.POSITIVE_INFINITY);
            case MAV_CMD.MAV_CMD_NAV_LOITER_TURNS -> turns(item, dt);
            case MAV_CMD.MAV_CMD_NAV_DELAY -> {
                timer += dt;
                yield timer >= Math.max(0, item.param1());
            }
            case MAV_CMD.MAV_CMD_NAV_LAND -> land(item, dt);
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
            double radius = item.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT ? firmware.acceptanceRadius(item, turn)
                    : firmware.performance().waypointRadius();
            boolean within = firmware.reach(body.craft(), t, radius, exitSpeed, dt);
            Optional<String> passed = within || !plainWaypoint || !pastFinishLine(legStart, t, body.craft().position())
                    ? Optional.empty() : firmware.passedText(item.seq(), body.craft().distanceTo(t));
            if (!within && passed.isEmpty()) {
                return false;
            }
            if (plainWaypoint) {
                passed.or(() -> firmware.arrivalText(item.seq(), body.craft().distanceTo(t), holdSeconds))
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
        firmware.completionText(item).ifPresent(s -> body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, s));
        return true;
    }

    /** LOITER_TURNS: to the circle's north point, then p1 turns of radius |p3| (0: the firmware's). */
    private boolean turns(MissionItem item, double dt) {
        Performance performance = firmware.performance();
        double r = Math.abs(item.param3()) > 0 ? Math.abs(item.param3()) : performance.loiterRadius();
        Position centre = target(item);
        if (phase == Phase.APPROACH) {
            if (!firmware.reach(body.craft(), Orbit.entry(centre, r), performance.precisionRadius(), 0, dt)) {
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
     * disarmed never completes it (ArduCopter: no MISSION_ITEM_REACHED for the landing), nor does one
     * whose mission stays at its landing (a QuadPlane). PX4 reports it reached as the descent begins,
     * and lands it armed: the mission's end disarms.
     */
    private boolean land(MissionItem item, double dt) {
        boolean landed = manoeuvre.step(dt);
        if (firmware.reachesLandingOnDescent() && !descending && manoeuvre.landedState() == MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING) {
            descending = true;
            body.reached(item.seq());
        }
        if (!landed) {
            return false;
        }
        if (manoeuvre.endsOnGround() && body.armed() && !firmware.reachesLandingOnDescent()) {
            body.disarm();
        }
        return !restartDue && firmware.completesLanding();
    }

    /** The item's position; lat = lon = 0 means here; z relative to home unless the frame is global. */
    private Position target(MissionItem item) {
        return target(item, body.craft().position());
    }

    /** The item's position, {@code here}'s when its lat = lon = 0. */
    private Position target(MissionItem item, Position here) {
        double lat = item.x() == 0 && item.y() == 0 ? here.latitudeDegrees() : item.x() * 1e-7;
        double lon = item.x() == 0 && item.y() == 0 ? here.longitudeDegrees() : item.y() * 1e-7;
        return Position.fromDegrees(lat, lon, altitude(item));
    }

    /**
     * The speed at which it leaves a waypoint: 0, stopping on it, when the waypoint holds (p1 > 0),
     * no nav item follows or its firmware stops before that one; else slowed for the turn to the next.
     */
    private double exitSpeed(MissionItem item, double turnFromHere) {
        MissionItem next = passedOnTo(item);
        if (next == null || !firmware.passesOn(next)) {
            return 0;
        }
        return firmware.performance().passingSpeed(body.craft().speed(), turnFromHere);
    }

    /** The nav item it flies on to from a waypoint without a hold time; null if none, or it holds. */
    private MissionItem passedOnTo(MissionItem item) {
        boolean waypoint = item.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT || item.command() == MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT;
        int after = waypoint && item.param1() <= 0 ? cursor.navFrom(item.seq() + 1) : -1;
        return after < 0 ? null : store.get(after);
    }

    /**
     * Location::past_interval_finish_line: {@code here} is past the line through {@code to} square to
     * the leg from {@code from}, or within a millimetre of it, as the simulated plane is when it has
     * flown onto the point itself; a leg under a millimetre long is passed at once.
     */
    private static boolean pastFinishLine(Position from, Position to, Position here) {
        double[] leg = from.displacementTo(to);
        double[] gone = from.displacementTo(here);
        double length = Math.hypot(leg[0], leg[1]);
        return length < 1e-3 || (gone[0] * leg[0] + gone[1] * leg[1]) / length >= length - 1e-3;
    }

    /** The turn at {@code item} from the leg to it from {@code from} onto the leg after it; pi if it holds or none follows. */
    private double turn(MissionItem item, Position from) {
        MissionItem next = passedOnTo(item);
        if (next == null) {
            return Math.PI;
        }
        Position at = target(item);
        double[] in = from.displacementTo(at);
        double[] out = at.displacementTo(target(next, at));
        if (Math.hypot(in[0], in[1]) < 1 || Math.hypot(out[0], out[1]) < 1) {
            return Math.PI;
        }
        return Math.abs(Math.IEEEremainder(Math.atan2(out[1], out[0]) - Math.atan2(in[1], in[0]), 2 * Math.PI));
    }

    private double altitude(MissionItem item) {
        return MissionCheck.relative(item.frame()) ? body.home().hae() + item.z() : item.z();
    }

    /** NAV commands are those below MAV_CMD_NAV_LAST (95), as AP_Mission::is_nav_cmd says. */
    static boolean nav(int command) {
        return command < MAV_CMD.MAV_CMD_NAV_LAST;
    }
}
