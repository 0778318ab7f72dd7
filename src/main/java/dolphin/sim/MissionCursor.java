package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import dolphin.mission.model.MissionItem;
import java.util.HashMap;
import java.util.Map;

/**
 * Where a simulated vehicle is in its stored mission and whether that mission runs, kept as
 * AP_Mission keeps it (docs/mavlink.md, "The simulated fleet and real ArduPilot"): its state, STOPPED,
 * RUNNING or COMPLETE; the nav item it is at, which MISSION_CURRENT reports (0: none); the next item
 * to run; and how often each DO_JUMP has jumped. An upload changes none of these: ArduPilot keeps its
 * place in a new mission, even one shorter than that place, until the mission is reset or started.
 */
final class MissionCursor {

    /** AP_Mission's mission_state. */
    enum MissionRun { STOPPED, RUNNING, COMPLETE }

    private final MissionStore store;
    private MissionRun run = MissionRun.STOPPED;
    private int next = 1;
    private int nav;
    /** Jumps made by each DO_JUMP (by seq) since the mission started. */
    private final Map<Integer, Integer> jumpsRun = new HashMap<>();

    MissionCursor(MissionStore store) {
        this.store = store;
    }

    MissionRun run() {
        return run;
    }

    boolean running() {
        return run == MissionRun.RUNNING;
    }

    /** The next item to run. */
    int next() {
        return next;
    }

    void next(int seq) {
        next = seq;
    }

    /** The nav item under way, or about to be, as MISSION_CURRENT reports it; 0 before any. */
    int nav() {
        return nav;
    }

    void nav(int seq) {
        nav = seq;
    }

    int jumps(int seq) {
        return jumpsRun.getOrDefault(seq, 0);
    }

    void jumped(int seq) {
        jumpsRun.merge(seq, 1, Integer::sum);
    }

    /** AP_Mission::reset: back to the first item with no nav item current and the jump counts at zero; the state stays. */
    void reset() {
        next = 1;
        nav = 0;
        jumpsRun.clear();
    }

    /** AP_Mission::start: from the first item, running. */
    void start() {
        reset();
        run = MissionRun.RUNNING;
    }

    /** ModeAuto::exit: leaving AUTO stops a running mission (MISSION_CURRENT says NOT_STARTED, never PAUSED). */
    void stop() {
        if (run == MissionRun.RUNNING) {
            run = MissionRun.STOPPED;
        }
    }

    void complete() {
        run = MissionRun.COMPLETE;
    }

    /** AP_Mission::clear: no mission, no place in it. */
    void cleared() {
        reset();
        run = MissionRun.STOPPED;
    }

    /**
     * AP_Mission::resume: a mission that had completed, has no current nav item, or whose place lies
     * past the end of what is stored now, starts from the top; any other runs on from its place.
     */
    void resume() {
        if (run == MissionRun.COMPLETE || nav == 0 || next >= store.count() || nav >= store.count()) {
            start();
        } else {
            run = MissionRun.RUNNING;
        }
    }

    /**
     * AP_Mission::set_current_cmd: the mission goes on from item {@code seq} (0 or a completed
     * mission: from the top, the jump counts at zero), its nav item the first from there. A mission not
     * running is left STOPPED there, to run from there when resumed. False when no nav item
     * follows: a running mission then ends (the caller completes it), one not running has no nav item.
     */
    boolean setCurrent(int seq) {
        if (seq >= store.count() || store.count() <= 1) {
            return false;
        }
        if (seq == 0 || run == MissionRun.COMPLETE) {
            jumpsRun.clear();
            seq = Math.max(1, seq);
        }
        int found = navFrom(seq);
        if (found < 0) {
            if (run != MissionRun.RUNNING) {
                nav = 0;
            }
            return false;
        }
        if (run != MissionRun.RUNNING) {
            run = MissionRun.STOPPED;
        }
        next = seq;
        nav = found;
        return true;
    }

    /** The first nav item from {@code seq} on, through DO_JUMPs that have jumps left; -1 if there is none. */
    int navFrom(int seq) {
        int at = seq;
        for (int guard = 0; guard <= store.count() && at < store.count(); guard++) {
            MissionItem item = store.get(at);
            if (MissionFlight.nav(item.command())) {
                return at;
            }
            at = item.command() == MAV_CMD.MAV_CMD_DO_JUMP ? jumpTarget(item) : at + 1;
        }
        return -1;
    }

    /** Where a DO_JUMP leads now: its target while it has jumps left, else the item after it; past the end for a bad target. */
    private int jumpTarget(MissionItem jump) {
        int target = (int) jump.param1();
        if (target <= 0 || target >= store.count()) {
            return store.count();
        }
        int times = (int) jump.param2();
        return times == MissionFlight.FOREVER || jumps(jump.seq()) < times ? target : jump.seq() + 1;
    }
}
