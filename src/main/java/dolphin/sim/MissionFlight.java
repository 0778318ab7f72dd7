package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_current;
import com.MAVLink.common.msg_mission_item_reached;
import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MISSION_STATE;
import dolphin.core.Position;
import dolphin.mavlink.mission.MissionItem;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;

/**
 * How a simulated vehicle flies its stored mission in AUTO, and RTL and LAND, on the fleet's tick in
 * clock time. Simple kinematics, ArduPilot's rules: a copter starts only after MAV_CMD_MISSION_START
 * (or when already flying) and disarms itself after 10 s armed on the ground in AUTO without it; a
 * plane starts as soon as it is armed in AUTO. DO items run when the nav item before them completes
 * (in the same tick, so their MISSION_ITEM_REACHED coalesces with it); CONDITION_DELAY runs beside
 * the next nav item. A copter hovers at the end of the mission, still in AUTO; a plane switches to
 * RTL and loiters over home.
 */
final class MissionFlight {

    static final double COPTER_SPEED = 10;      // WPNAV_SPEED
    static final double PLANE_SPEED = 20;       // cruise airspeed
    static final double COPTER_CLIMB = 2.5;     // WPNAV_SPEED_UP, also the takeoff climb
    static final double COPTER_SINK = 1.5;      // WPNAV_SPEED_DN, also LAND_SPEED_HIGH
    static final double LAND_SPEED = 0.5;       // LAND_SPEED, below LAND_ALT_LOW
    static final double LAND_ALT_LOW = 10;
    static final double PLANE_CLIMB = 5;
    static final double PLANE_SINK = 3;
    static final double COPTER_WP_RADIUS = 1;   // ArduCopter SITL reaches waypoints within 0.6 to 1.5 m
    static final double PLANE_WP_RADIUS = 55;   // WP_RADIUS
    static final double COPTER_TURN_RADIUS = 10;
    static final double PLANE_LOITER_RADIUS = 60; // WP_LOITER_RAD
    static final double RTL_ALT = 15;           // RTL_ALT (copter), metres above home
    static final double DISARM_DELAY = 10;
    /** DO_JUMP's repeat count meaning for ever (AP_MISSION_JUMP_REPEAT_FOREVER). */
    static final int FOREVER = -1;
    static final double LANDED_HEIGHT = 0.5;
    static final int COPTER_LAND_MODE = COPTER_MODE.COPTER_MODE_LAND;

    private static final Set<Integer> CAMERA = Set.of(MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE,
            MAV_CMD.MAV_CMD_DO_DIGICAM_CONTROL, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST);

    /** What the flight needs from its vehicle. */
    interface Body {
        Position position();

        void place(Position p);

        Position home();

        boolean armed();

        int mode();

        void switchMode(int mode);

        /** Touched down: landed and disarmed. */
        void touchdown();

        void send(MAVLinkMessage m);

        void text(int severity, String text);
    }

    private enum Phase { APPROACH, HOLD, CIRCLE, CLIMB, RETURN, DESCEND, LOITER }

    private final VehicleKind kind;
    private final MissionStore store;
    private final Body body;
    private int current = 1;
    private boolean started;
    private boolean complete;
    private boolean autoArmed;
    private double speed;
    private double heading;
    private double groundSeconds;
    private int reachedPending = -1;
    private int cameraCommands;
    // the nav item under way
    private int active = -1;
    private Phase phase;
    private double timer;
    private double angle;
    private Position anchor;
    // RTL and LAND modes
    private Phase modePhase;
    // a CONDITION_DELAY running beside the nav item
    private int conditionSeq = -1;
    private double conditionLeft;
    /** Jumps made by each DO_JUMP (by seq) since the mission started. */
    private final Map<Integer, Integer> jumpsRun = new HashMap<>();
    /** The last MISSION_CURRENT announced (seq/total/state); a change is sent at once, as ArduPilot does. */
    private String lastCurrent = "0/0/" + MISSION_STATE.MISSION_STATE_NO_MISSION;

    MissionFlight(VehicleKind kind, MissionStore store, Body body) {
        this.kind = kind;
        this.store = store;
        this.body = body;
        this.speed = defaultSpeed();
    }

    int cameraCommands() {
        return cameraCommands;
    }

    int current() {
        return current;
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
        return body.mode() == kind.autoMode && body.armed() ? MISSION_STATE.MISSION_STATE_ACTIVE
                : MISSION_STATE.MISSION_STATE_PAUSED;
    }

    /** Armed and running a mission in AUTO: ArduPilot then refuses MISSION_CLEAR_ALL. */
    boolean flyingMission() {
        return body.armed() && body.mode() == kind.autoMode && started && !complete;
    }

    boolean landed() {
        return body.position().hae() - body.home().hae() <= LANDED_HEIGHT;
    }

    /** ModeAuto::init: armed and landed, AUTO needs a takeoff as the first nav item. */
    boolean autoAllowed() {
        if (kind != VehicleKind.COPTER || !body.armed() || !landed()) {
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

    /** Called after every mode change. */
    void modeChanged(int from, int to) {
        if (to == from) {
            return;
        }
        modePhase = null;
        active = -1;
        groundSeconds = 0;
        if (to == kind.autoMode) {
            if (complete || current >= store.count()) {
                restart();
            }
            speed = defaultSpeed();
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
        complete = false;
        active = -1;
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
        started = false;
        complete = false;
        active = -1;
        jumpsRun.clear();
    }

    void disarmed() {
        autoArmed = false;
        groundSeconds = 0;
    }

    void tick(double dt) {
        if (body.armed()) {
            int mode = body.mode();
            if (mode == kind.autoMode) {
                auto(dt);
            } else if (mode == kind.rtlMode) {
                returnHome(dt, false);
            } else if (kind == VehicleKind.COPTER && mode == COPTER_LAND_MODE) {
                descend(dt);
            }
        }
        flushReached();
        announceCurrent(false);
    }

    /** MISSION_CURRENT: seq is the current nav item (0 once complete), total excludes home. */
    MAVLinkMessage missionCurrent() {
        msg_mission_current c = new msg_mission_current();
        int state = state();
        c.seq = state == MISSION_STATE.MISSION_STATE_COMPLETE || state == MISSION_STATE.MISSION_STATE_NO_MISSION ? 0
                : Math.min(current, store.count() - 1);
        c.total = Math.max(0, store.count() - 1);
        c.mission_state = (short) state;
        c.mission_mode = (short) (body.mode() == kind.autoMode ? 1 : 0);
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

    private void auto(double dt) {
        if (kind == VehicleKind.COPTER && !autoArmed) {
            if (!landed()) {
                autoArmed = true;
            } else {
                groundSeconds += dt;
                if (groundSeconds >= DISARM_DELAY) {
                    body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Disarming: landed in AUTO without MISSION_START");
                    body.touchdown();
                }
                return;
            }
        }
        groundSeconds = 0;
        if (complete || store.count() <= 1) {
            return; // a copter hovers where the mission left it
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
                runDo(item);
                current++;
                continue;
            }
            if (active != current) {
                begin(item);
            }
            if (!step(item, dt)) {
                return;
            }
            reached(current, true);
            current++;
            active = -1;
            dt = 0;
            if (!body.armed()) {
                // landed and disarmed by the item: the mission goes on only through its DO items
                while (current < store.count() && !nav(store.get(current).command())
                        && store.get(current).command() != MAV_CMD.MAV_CMD_DO_JUMP) {
                    runDo(store.get(current));
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
        if (kind == VehicleKind.PLANE && body.armed()) {
            body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Mission complete, changing mode to RTL");
            int from = body.mode();
            body.switchMode(kind.rtlMode);
            modeChanged(from, kind.rtlMode);
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

    private void runDo(MissionItem item) {
        int cmd = item.command();
        if (cmd == MAV_CMD.MAV_CMD_DO_CHANGE_SPEED) {
            if (item.param2() > 0) {
                speed = item.param2();
            }
        } else if (CAMERA.contains(cmd)) {
            cameraCommands++;
        } else if (cmd == MAV_CMD.MAV_CMD_CONDITION_DELAY) {
            conditionSeq = item.seq();
            conditionLeft = Math.max(0, item.param1());
            return; // reached when the delay has passed
        }
        reached(item.seq(), false);
    }

    private void conditionStep(double dt) {
        if (conditionSeq >= 0) {
            conditionLeft -= dt;
            if (conditionLeft <= 0) {
                reached(conditionSeq, false);
                conditionSeq = -1;
            }
        }
    }

    private void begin(MissionItem item) {
        active = current;
        phase = Phase.APPROACH;
        timer = 0;
        angle = 0;
        anchor = null;
        modePhase = null;
    }

    /** One tick of the current nav item; true when it is complete. */
    private boolean step(MissionItem item, double dt) {
        return switch (item.command()) {
            case MAV_CMD.MAV_CMD_NAV_TAKEOFF -> takeoff(item, dt);
            case MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT -> waypoint(item, dt, item.param1());
            case MAV_CMD.MAV_CMD_NAV_LOITER_TIME -> waypoint(item, dt, item.param1());
            case MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM -> {
                if (phase == Phase.APPROACH && reach(target(item), dt, radius(item))) {
                    phase = Phase.LOITER;
                }
                if (phase == Phase.LOITER) {
                    hold(target(item), dt);
                }
                yield false;
            }
            case MAV_CMD.MAV_CMD_NAV_LOITER_TURNS -> turns(item, dt);
            case MAV_CMD.MAV_CMD_NAV_DELAY -> {
                timer += dt;
                yield timer >= Math.max(0, item.param1());
            }
            case MAV_CMD.MAV_CMD_NAV_LAND -> land(item, dt);
            case MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH -> returnHome(dt, true);
            default -> {
                body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Skipping invalid cmd #" + item.seq());
                yield true;
            }
        };
    }

    private boolean takeoff(MissionItem item, double dt) {
        double alt = altitude(item);
        Position p = body.position();
        double up = alt - p.hae();
        if (up <= 0.05) {
            return true;
        }
        if (kind == VehicleKind.COPTER) {
            body.place(p.displace(0, 0, -Math.min(up, COPTER_CLIMB * dt)));
        } else {
            double d = speed * dt;
            body.place(p.displace(d * Math.cos(heading), d * Math.sin(heading), -Math.min(up, PLANE_CLIMB * dt)));
        }
        return alt - body.position().hae() <= 0.05;
    }

    /** Flies to the item's position, then holds there for {@code holdSeconds}. */
    private boolean waypoint(MissionItem item, double dt, double holdSeconds) {
        Position t = target(item);
        if (phase == Phase.APPROACH) {
            if (!reach(t, dt, radius(item))) {
                return false;
            }
            reachedText(item.seq());
            phase = Phase.HOLD;
            dt = 0;
        }
        hold(t, dt);
        timer += dt;
        return timer >= Math.max(0, holdSeconds);
    }

    private boolean turns(MissionItem item, double dt) {
        double r = Math.abs(item.param3()) > 0 ? Math.abs(item.param3())
                : kind == VehicleKind.COPTER ? COPTER_TURN_RADIUS : PLANE_LOITER_RADIUS;
        Position center = target(item);
        if (phase == Phase.APPROACH) {
            if (!reach(center.displace(r, 0, 0), dt, kind == VehicleKind.COPTER ? COPTER_WP_RADIUS : 5)) {
                return false;
            }
            phase = Phase.CIRCLE;
            dt = 0;
        }
        angle += speed / r * dt;
        double done = 2 * Math.PI * Math.max(0, item.param1());
        double a = Math.min(angle, done);
        body.place(center.displace(r * Math.cos(a), r * Math.sin(a), 0));
        return angle >= done;
    }

    private boolean land(MissionItem item, double dt) {
        if (phase == Phase.APPROACH) {
            Position p = body.position();
            Position over = item.x() == 0 && item.y() == 0 ? p
                    : Position.fromDegrees(item.x() * 1e-7, item.y() * 1e-7, p.hae());
            if (!reach(over, dt, kind == VehicleKind.COPTER ? COPTER_WP_RADIUS : PLANE_WP_RADIUS / 10)) {
                return false;
            }
            phase = Phase.DESCEND;
            dt = 0;
        }
        return descend(dt);
    }

    /** Descends where it is, ArduCopter's LAND speeds; true on touchdown (disarmed). */
    private boolean descend(double dt) {
        Position p = body.position();
        double height = p.hae() - body.home().hae();
        double rate = height > LAND_ALT_LOW ? COPTER_SINK : LAND_SPEED;
        double down = Math.min(Math.max(0, height), rate * dt);
        body.place(p.displace(0, 0, down));
        if (height - down <= 0.01) {
            body.place(Position.fromDegrees(p.latitudeDegrees(), p.longitudeDegrees(), body.home().hae()));
            body.touchdown();
            return true;
        }
        return false;
    }

    /**
     * RTL: a copter climbs to RTL_ALT above home if lower, flies home and lands; a plane flies home
     * at its height and loiters over it. As a mission item it completes on touchdown (copter) or
     * within WP_RADIUS of home (plane).
     */
    private boolean returnHome(double dt, boolean asItem) {
        Position home = body.home();
        if (modePhase == null) {
            modePhase = kind == VehicleKind.COPTER ? Phase.CLIMB : Phase.RETURN;
            anchor = null;
        }
        Position p = body.position();
        switch (modePhase) {
            case CLIMB -> {
                double alt = home.hae() + RTL_ALT;
                if (p.hae() >= alt - 0.05 || reach(Position.fromDegrees(p.latitudeDegrees(), p.longitudeDegrees(), alt), dt, 0.05)) {
                    modePhase = Phase.RETURN;
                }
                return false;
            }
            case RETURN -> {
                Position over = Position.fromDegrees(home.latitudeDegrees(), home.longitudeDegrees(), p.hae());
                double radius = kind == VehicleKind.COPTER ? COPTER_WP_RADIUS : PLANE_WP_RADIUS;
                if (reach(over, dt, radius)) {
                    modePhase = kind == VehicleKind.COPTER ? Phase.DESCEND : Phase.LOITER;
                    return asItem && kind == VehicleKind.PLANE;
                }
                return false;
            }
            case DESCEND -> {
                return descend(dt);
            }
            default -> {
                hold(Position.fromDegrees(home.latitudeDegrees(), home.longitudeDegrees(), p.hae()), dt);
                return asItem;
            }
        }
    }

    /** Stays at {@code t}: a copter hovers, a plane circles it at WP_LOITER_RAD. */
    private void hold(Position t, double dt) {
        if (kind == VehicleKind.COPTER) {
            return;
        }
        angle += speed / PLANE_LOITER_RADIUS * dt;
        body.place(t.displace(PLANE_LOITER_RADIUS * Math.cos(angle), PLANE_LOITER_RADIUS * Math.sin(angle), 0));
    }

    /**
     * Moves towards {@code t}: horizontally at the current speed, vertically at the climb or sink
     * rate; true once within {@code radius} horizontally (and, for a copter, at its height).
     */
    private boolean reach(Position t, double dt, double radius) {
        Position p = body.position();
        double[] ned = p.displacementTo(t);
        double h = Math.hypot(ned[0], ned[1]);
        double f = h <= 0 ? 0 : Math.min(1, speed * dt / h);
        if (h > 0.01) {
            heading = Math.atan2(ned[1], ned[0]);
        }
        double up = -ned[2];
        double climb = kind == VehicleKind.COPTER ? COPTER_CLIMB : PLANE_CLIMB;
        double sink = kind == VehicleKind.COPTER ? COPTER_SINK : PLANE_SINK;
        double dz = Math.max(-sink * dt, Math.min(climb * dt, up));
        body.place(p.displace(ned[0] * f, ned[1] * f, -dz));
        double left = h * (1 - f);
        return left <= radius && (kind == VehicleKind.PLANE || Math.abs(up - dz) <= 0.1);
    }

    private double radius(MissionItem item) {
        if (item.param2() > 0 && item.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT) {
            return item.param2();
        }
        return kind == VehicleKind.COPTER ? COPTER_WP_RADIUS : PLANE_WP_RADIUS;
    }

    /** The item's position; lat = lon = 0 means here; z relative to home unless the frame is global. */
    private Position target(MissionItem item) {
        Position p = body.position();
        double lat = item.x() == 0 && item.y() == 0 ? p.latitudeDegrees() : item.x() * 1e-7;
        double lon = item.x() == 0 && item.y() == 0 ? p.longitudeDegrees() : item.y() * 1e-7;
        return Position.fromDegrees(lat, lon, altitude(item));
    }

    private double altitude(MissionItem item) {
        return MissionCheck.relative(item.frame()) ? body.home().hae() + item.z() : item.z();
    }

    private void reachedText(int seq) {
        body.text(MAV_SEVERITY.MAV_SEVERITY_INFO, "Reached command #" + seq);
    }

    private void reached(int seq, boolean navItem) {
        if (navItem && phase != Phase.HOLD) {
            reachedText(seq);
        }
        reachedPending = seq;
    }

    /** GCS::send_mission_item_reached_message: one pending index, sent at most once per tick. */
    private void flushReached() {
        if (reachedPending >= 0) {
            msg_mission_item_reached r = new msg_mission_item_reached();
            r.seq = reachedPending;
            reachedPending = -1;
            body.send(r);
        }
    }

    private double defaultSpeed() {
        return kind == VehicleKind.COPTER ? COPTER_SPEED : PLANE_SPEED;
    }

    /** NAV commands are those below MAV_CMD_NAV_LAST (95), as AP_Mission::is_nav_cmd says. */
    static boolean nav(int command) {
        return command < MAV_CMD.MAV_CMD_NAV_LAST;
    }
}
