package dolphin.mission.flight;

import com.MAVLink.enums.MISSION_STATE;
import dolphin.mavlink.VehicleState;

/**
 * The verdict, read from MISSION_CURRENT, of a vehicle that checks a mission after its upload (PX4's
 * navigator: MissionBase::check_mission_valid). PX4 names the new mission at once (mission_id, the CRC32 its
 * upload's final MISSION_ACK carried) but keeps the earlier mission's state, with no current item (seq
 * UINT16_MAX), until its navigator has checked it; then the state is NOT_STARTED (ACTIVE or PAUSED in
 * AUTO.MISSION), or NO_MISSION for a mission it found infeasible. A mission uploaded again unchanged is not
 * checked again: it keeps its state, COMPLETE after a flight, which MISSION_START from the first item flies
 * again. A vehicle that names no missions (older firmware) is judged by the total and a state a valid
 * mission has; it cannot tell its verdict on this mission from the earlier one's.
 * <p>
 * The first MISSION_CURRENT with a current item may still carry the earlier state: PX4 sends one as soon as
 * the check's result gives the current item, but works its state out again only after a newer vehicle_status
 * (MavlinkMissionManager::update_mission_state; commander publishes one at least every 0.5 s). And PX4 may
 * never show the current item: on SITL after a flight, a mission refused under a new fence kept seq UINT16_MAX
 * while its state went from COMPLETE to NO_MISSION (the recording px4-copter-refused-after-flight). A report's
 * state is therefore the check's
 * <ul>
 *   <li>when it names a current item and its state differs from the one reported before the first report with
 *       one (it was worked out from the check's result);</li>
 *   <li>from the third report in a row naming the current item with the same state: PX4 sends them at 1 Hz
 *       besides the one the check's result triggers, so the third is at least a second after the first, past
 *       a vehicle_status;</li>
 *   <li>from the third report in a row with the same state, current item or not, when that state differs from
 *       the one reported before the mission was named: a state that changed and held.</li>
 * </ul>
 * Fed on the communications thread ({@link #heard}), read on the executor's.
 */
final class FeasibilityWatch {

    enum Feasibility { PENDING, FEASIBLE, INFEASIBLE }

    /** MISSION_CURRENT's seq and total when there is none (UINT16_MAX). */
    private static final int NONE = 65535;
    /** Reports in a row with one state after which it is the check's (see the class). */
    private static final int SETTLED_REPORTS = 3;

    private final int items;
    private final long idBefore;
    private long idUploaded;
    /** The last MISSION_CURRENT heard: whether it named a current item, its total (0: none), state and mission id. */
    private boolean lastChecked;
    private int lastTotal;
    private int lastState;
    private long lastId;
    /** The mission the reports in a row name, for as many items; 0: none. The state reported before them. */
    private long namedId;
    private int stateBeforeNamed;
    /** Of those reports, the last ones with the last state: all of them, and those in a row naming a current item. */
    private int steady;
    private int steadyChecked;
    /** Of the last of those reports in a row that name a current item: the state reported before them, and whether one gave another. */
    private int stateBeforeChecked;
    private boolean checkedChanged;

    /**
     * @param items the mission's items without home (MISSION_CURRENT.total)
     * @param before the vehicle's state when the upload began: the mission it named then, 0 when none, and its report
     */
    FeasibilityWatch(int items, VehicleState before) {
        this.items = items;
        this.idBefore = before.missionId();
        lastChecked = before.missionSeq() >= 0;
        lastTotal = before.missionTotal();
        lastState = before.missionState();
        lastId = before.missionId();
    }

    /** The id the upload's final MISSION_ACK (or the verifying download's MISSION_COUNT) gave; 0 when none. */
    synchronized void uploaded(long id) {
        idUploaded = id;
    }

    /** A MISSION_CURRENT as the vehicle sent it, on the communications thread, in the order it was sent. */
    synchronized void heard(int seq, int total, int state, long id) {
        boolean checked = seq != NONE;
        if (total != items || id == 0) {
            namedId = 0;
        } else {
            boolean sameRun = id == namedId;
            if (!sameRun) {
                namedId = id;
                stateBeforeNamed = lastState;
            }
            boolean same = sameRun && state == lastState;
            steady = same ? steady + 1 : 1;
            steadyChecked = !checked ? 0 : same ? steadyChecked + 1 : 1;
            if (checked && !(sameRun && lastChecked)) {
                stateBeforeChecked = lastState;
                checkedChanged = false;
            }
            checkedChanged |= checked && state != stateBeforeChecked;
        }
        lastChecked = checked;
        lastTotal = total == NONE ? 0 : total;
        lastState = state;
        lastId = id;
    }

    /** Whether both the upload and the vehicle's MISSION_CURRENT name missions, so its state can be told to be this mission's. */
    synchronized boolean namesMissions() {
        return idUploaded != 0 && lastId != 0;
    }

    /** Whether the vehicle already held this very mission, so it keeps its earlier verdict and state. */
    synchronized boolean unchanged() {
        return idUploaded != 0 && idUploaded == idBefore;
    }

    synchronized Feasibility verdict() {
        if (lastTotal != items) {
            return Feasibility.PENDING;
        }
        if (!namesMissions()) {
            return validBeforeStart(lastState) ? Feasibility.FEASIBLE : Feasibility.PENDING;
        }
        if (lastId != idUploaded || !unchanged() && !settled()) {
            return Feasibility.PENDING;     // another mission's state, or this one's not checked yet
        }
        if (lastState == MISSION_STATE.MISSION_STATE_NO_MISSION) {
            return Feasibility.INFEASIBLE;
        }
        return validBeforeStart(lastState) || unchanged() && lastState == MISSION_STATE.MISSION_STATE_COMPLETE
                ? Feasibility.FEASIBLE : Feasibility.PENDING;
    }

    /** Whether the last report's state is the check's on this mission (see the class). */
    private boolean settled() {
        return namedId == idUploaded && (lastChecked && checkedChanged || steadyChecked >= SETTLED_REPORTS
                || steady >= SETTLED_REPORTS && lastState != stateBeforeNamed);
    }

    /** The items the last MISSION_CURRENT counted, 0 when it counted none. */
    synchronized int lastTotal() {
        return lastTotal;
    }

    /** Whether the last MISSION_CURRENT, of a vehicle that names missions, named no current item: no check shown. */
    synchronized boolean unchecked() {
        return namesMissions() && !lastChecked;
    }

    /** The state the last MISSION_CURRENT gave. */
    synchronized int lastState() {
        return lastState;
    }

    /** A state a valid mission has before its flight: NOT_STARTED; ACTIVE or PAUSED when PX4 is still in AUTO.MISSION. */
    private static boolean validBeforeStart(int state) {
        return state == MISSION_STATE.MISSION_STATE_NOT_STARTED || state == MISSION_STATE.MISSION_STATE_ACTIVE
                || state == MISSION_STATE.MISSION_STATE_PAUSED;
    }
}
