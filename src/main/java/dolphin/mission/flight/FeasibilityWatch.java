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
 */
final class FeasibilityWatch {

    enum Feasibility { PENDING, FEASIBLE, INFEASIBLE }

    private final int items;
    private final long idBefore;
    private final long idUploaded;

    /**
     * @param items the mission's items without home (MISSION_CURRENT.total)
     * @param idBefore the mission id the vehicle named when the upload began, 0 when none
     * @param idUploaded the id the upload's final MISSION_ACK (or the verifying download's MISSION_COUNT) gave, 0 when none
     */
    FeasibilityWatch(int items, long idBefore, long idUploaded) {
        this.items = items;
        this.idBefore = idBefore;
        this.idUploaded = idUploaded;
    }

    /** Whether both the upload and the vehicle's MISSION_CURRENT name missions, so its state can be told to be this mission's. */
    boolean namesMissions(VehicleState s) {
        return idUploaded != 0 && s.missionId() != 0;
    }

    /** Whether the vehicle already held this very mission, so it keeps its earlier verdict and state. */
    boolean unchanged() {
        return idUploaded != 0 && idUploaded == idBefore;
    }

    Feasibility verdict(VehicleState s) {
        if (s.missionTotal() != items) {
            return Feasibility.PENDING;
        }
        int state = s.missionState();
        if (!namesMissions(s)) {
            return validBeforeStart(state) ? Feasibility.FEASIBLE : Feasibility.PENDING;
        }
        if (s.missionId() != idUploaded || !unchanged() && s.missionSeq() < 0) {
            return Feasibility.PENDING;     // another mission's state, or this one's not checked yet
        }
        if (state == MISSION_STATE.MISSION_STATE_NO_MISSION) {
            return Feasibility.INFEASIBLE;
        }
        return validBeforeStart(state) || unchanged() && state == MISSION_STATE.MISSION_STATE_COMPLETE
                ? Feasibility.FEASIBLE : Feasibility.PENDING;
    }

    /** A state a valid mission has before its flight: NOT_STARTED; ACTIVE or PAUSED when PX4 is still in AUTO.MISSION. */
    private static boolean validBeforeStart(int state) {
        return state == MISSION_STATE.MISSION_STATE_NOT_STARTED || state == MISSION_STATE.MISSION_STATE_ACTIVE
                || state == MISSION_STATE.MISSION_STATE_PAUSED;
    }
}
