package dolphin.mission.flight

import com.MAVLink.enums.MISSION_STATE
import dolphin.mavlink.Autopilot
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import spock.lang.Specification

import static dolphin.mission.flight.FeasibilityWatch.Feasibility.FEASIBLE
import static dolphin.mission.flight.FeasibilityWatch.Feasibility.INFEASIBLE
import static dolphin.mission.flight.FeasibilityWatch.Feasibility.PENDING

/**
 * The verdict of a PX4 vehicle on an uploaded mission of 3 items, read from MISSION_CURRENT as PX4 sends it
 * (MavlinkMissionManager::send_mission_current): the new mission's id at once, its state once the navigator
 * checked it (seq no longer UINT16_MAX); an unchanged mission keeps its state.
 */
class FeasibilityWatchSpec extends Specification {

    static final int NOT_STARTED = MISSION_STATE.MISSION_STATE_NOT_STARTED
    static final int ACTIVE = MISSION_STATE.MISSION_STATE_ACTIVE
    static final int PAUSED = MISSION_STATE.MISSION_STATE_PAUSED
    static final int COMPLETE = MISSION_STATE.MISSION_STATE_COMPLETE
    static final int NO_MISSION = MISSION_STATE.MISSION_STATE_NO_MISSION
    static final int NO_ITEM = 65535

    static VehicleState px4(int seq, int total, int state, long id) {
        VehicleState.initial(Autopilot.PX4, VehicleFamily.COPTER).withMissionCurrent(seq, total, state, id)
    }

    def "a new mission (id 0xB, the vehicle held 0xA) is judged only by its own id, once checked: #why"() {
        expect:
        new FeasibilityWatch(3, 0xA, 0xB).verdict(px4(seq, total, state, id)) == verdict

        where:
        seq     | total | state       | id  || verdict    | why
        NO_ITEM | 3     | COMPLETE    | 0xB || PENDING    | 'the earlier flight\'s COMPLETE before the check'
        NO_ITEM | 3     | NOT_STARTED | 0xB || PENDING    | 'the earlier mission\'s NOT_STARTED before the check'
        NO_ITEM | 3     | NO_MISSION  | 0xB || PENDING    | 'the earlier mission\'s NO_MISSION before the check'
        0       | 3     | NOT_STARTED | 0xA || PENDING    | 'the earlier mission named'
        0       | 3     | NO_MISSION  | 0xA || PENDING    | 'the earlier mission named, found infeasible'
        0       | 2     | NOT_STARTED | 0xB || PENDING    | 'another count'
        0       | 3     | COMPLETE    | 0xB || PENDING    | 'COMPLETE, which a checked new mission never is'
        0       | 3     | NOT_STARTED | 0xB || FEASIBLE   | 'checked: NOT_STARTED'
        0       | 3     | ACTIVE      | 0xB || FEASIBLE   | 'checked in AUTO.MISSION: ACTIVE'
        0       | 3     | PAUSED      | 0xB || FEASIBLE   | 'checked after a pause: PAUSED'
        0       | 3     | NO_MISSION  | 0xB || INFEASIBLE | 'checked: NO_MISSION'
    }

    def "the same mission again (id 0xB before and after) is not checked again: its state stands, COMPLETE included: #why"() {
        expect:
        new FeasibilityWatch(3, 0xB, 0xB).verdict(px4(seq, 3, state, 0xB)) == verdict

        where:
        seq | state       || verdict    | why
        3   | COMPLETE    || FEASIBLE   | 'flown before'
        0   | NOT_STARTED || FEASIBLE   | 'never flown'
        0   | NO_MISSION  || INFEASIBLE | 'found infeasible before'
    }

    def "without ids (the vehicle or the upload names none) a valid state for as many items is all there is: #why"() {
        expect:
        new FeasibilityWatch(3, before, uploaded).verdict(px4(0, total, state, id)) == verdict

        where:
        before | uploaded | total | state       | id  || verdict  | why
        0      | 0        | 3     | NOT_STARTED | 0   || FEASIBLE | 'NOT_STARTED'
        0      | 0        | 3     | ACTIVE      | 0   || FEASIBLE | 'ACTIVE'
        0      | 0        | 3     | COMPLETE    | 0   || PENDING  | 'COMPLETE, maybe the earlier flight\'s'
        0      | 0        | 3     | NO_MISSION  | 0   || PENDING  | 'NO_MISSION, maybe the earlier mission\'s'
        0      | 0        | 2     | NOT_STARTED | 0   || PENDING  | 'another count'
        0      | 0xB      | 3     | NOT_STARTED | 0   || FEASIBLE | 'an id uploaded, none in MISSION_CURRENT'
        0xA    | 0        | 3     | NOT_STARTED | 0xA || FEASIBLE | 'an id in MISSION_CURRENT, none uploaded'
    }

    def "names missions only when both the upload and MISSION_CURRENT give an id; unchanged only for the same non-zero id"() {
        expect:
        new FeasibilityWatch(3, 0, 0xB).namesMissions(px4(0, 3, NOT_STARTED, 0xB))
        !new FeasibilityWatch(3, 0, 0xB).namesMissions(px4(0, 3, NOT_STARTED, 0))
        !new FeasibilityWatch(3, 0, 0).namesMissions(px4(0, 3, NOT_STARTED, 0xB))
        new FeasibilityWatch(3, 0xB, 0xB).unchanged()
        !new FeasibilityWatch(3, 0xA, 0xB).unchanged()
        !new FeasibilityWatch(3, 0, 0).unchanged()
    }
}
