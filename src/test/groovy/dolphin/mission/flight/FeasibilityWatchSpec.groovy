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
 * checked it (seq no longer UINT16_MAX) and PX4 worked the state out again; an unchanged mission keeps its state.
 */
class FeasibilityWatchSpec extends Specification {

    static final int NOT_STARTED = MISSION_STATE.MISSION_STATE_NOT_STARTED
    static final int ACTIVE = MISSION_STATE.MISSION_STATE_ACTIVE
    static final int PAUSED = MISSION_STATE.MISSION_STATE_PAUSED
    static final int COMPLETE = MISSION_STATE.MISSION_STATE_COMPLETE
    static final int NO_MISSION = MISSION_STATE.MISSION_STATE_NO_MISSION
    static final int NO_ITEM = 65535

    /** A watch begun when the vehicle reported (seq, total, state, id), given the upload's id, then hearing each report. */
    static FeasibilityWatch watch(List before, long uploaded, List<List> reports) {
        def (seq, total, state, id) = before
        def w = new FeasibilityWatch(3, VehicleState.initial(Autopilot.PX4, VehicleFamily.COPTER).withMissionCurrent(seq, total, state, id))
        w.uploaded(uploaded)
        reports.each { r -> w.heard(r[0], r[1], r[2], r[3]) }
        w
    }

    def "a new mission (id 0xB, the vehicle held 0xA) is judged only by its own id, once checked: #why"() {
        expect:
        watch([2, 3, COMPLETE, 0xA], 0xB, [[NO_ITEM, 3, COMPLETE, 0xB], [seq, total, state, id]]).verdict() == verdict

        where:
        seq     | total | state       | id  || verdict    | why
        NO_ITEM | 3     | COMPLETE    | 0xB || PENDING    | 'the earlier flight\'s COMPLETE before the check'
        NO_ITEM | 3     | NOT_STARTED | 0xB || PENDING    | 'NOT_STARTED before the check'
        NO_ITEM | 3     | NO_MISSION  | 0xB || PENDING    | 'NO_MISSION before the check'
        0       | 3     | NOT_STARTED | 0xA || PENDING    | 'the earlier mission named'
        0       | 3     | NO_MISSION  | 0xA || PENDING    | 'the earlier mission named, found infeasible'
        0       | 2     | NOT_STARTED | 0xB || PENDING    | 'another count'
        0       | 3     | COMPLETE    | 0xB || PENDING    | 'COMPLETE, which a checked new mission never is'
        0       | 3     | NOT_STARTED | 0xB || FEASIBLE   | 'checked: NOT_STARTED'
        0       | 3     | ACTIVE      | 0xB || FEASIBLE   | 'checked in AUTO.MISSION: ACTIVE'
        0       | 3     | PAUSED      | 0xB || FEASIBLE   | 'checked after a pause: PAUSED'
        0       | 3     | NO_MISSION  | 0xB || INFEASIBLE | 'checked: NO_MISSION'
    }

    def "the first checked report may carry the earlier state: a state that did not change is taken from the third checked report (#earlier, then #checked)"() {
        given: 'the vehicle held 0xA in #earlier; 0xB named at once with that state and no current item'
        def w = watch([0, 3, earlier, 0xA], 0xB, [[NO_ITEM, 3, earlier, 0xB]])

        when:
        List verdicts = (1..4).collect {
            w.heard(0, 3, checked, 0xB)
            w.verdict()
        }

        then:
        verdicts == [PENDING, PENDING, verdict, verdict]

        where:
        earlier     | checked     || verdict
        NOT_STARTED | NOT_STARTED || FEASIBLE
        NO_MISSION  | NO_MISSION  || INFEASIBLE
        ACTIVE      | ACTIVE      || FEASIBLE
    }

    def "the earlier state in the first checked report is not the verdict; the state worked out after it is, at once: #why"() {
        given:
        def w = watch([0, 3, earlier, 0xA], 0xB, [[NO_ITEM, 3, earlier, 0xB]])

        when:
        w.heard(0, 3, earlier, 0xB)
        def first = w.verdict()
        w.heard(0, 3, worked, 0xB)

        then:
        first == PENDING
        w.verdict() == verdict

        where:
        earlier     | worked      || verdict    | why
        NOT_STARTED | NO_MISSION  || INFEASIBLE | 'an earlier valid mission, this one refused'
        NO_MISSION  | NOT_STARTED || FEASIBLE   | 'an earlier refused mission, this one valid'
        COMPLETE    | NO_MISSION  || INFEASIBLE | 'the earlier flight, this one refused (SitlPx4Spec\'s fence)'
    }

    def "a report with no current item, or for another count, begins the count of checked reports again: #why"() {
        given:
        def w = watch([0, 3, NOT_STARTED, 0xA], 0xB, [[0, 3, NOT_STARTED, 0xB], [0, 3, NOT_STARTED, 0xB], between])

        when:
        w.heard(0, 3, NOT_STARTED, 0xB)
        def once = w.verdict()
        w.heard(0, 3, NOT_STARTED, 0xB)
        def twice = w.verdict()
        w.heard(0, 3, NOT_STARTED, 0xB)

        then:
        once == PENDING
        twice == PENDING
        w.verdict() == FEASIBLE

        where:
        between                       || why
        [NO_ITEM, 3, NOT_STARTED, 0xB] || 'no current item'
        [0, 2, NOT_STARTED, 0xB]       || 'another count'
        [0, 3, NOT_STARTED, 0xA]       || 'the earlier mission'
    }

    def "a vehicle that never names the current item: a state that changed from the earlier one and held for three reports is the verdict (#earlier, then #states)"() {
        given: 'the vehicle held 0xA in #earlier; 0xB is named with no current item from then on'
        def w = watch([0, 3, earlier, 0xA], 0xB, [])

        when:
        List verdicts = states.collect { state ->
            w.heard(NO_ITEM, 3, state, 0xB)
            w.verdict()
        }

        then:
        verdicts == expected

        where:
        earlier     | states                                             || expected
        ACTIVE      | [COMPLETE, NO_MISSION, NO_MISSION, NO_MISSION]     || [PENDING, PENDING, PENDING, INFEASIBLE]
        COMPLETE    | [NOT_STARTED, NOT_STARTED, NOT_STARTED]            || [PENDING, PENDING, FEASIBLE]
        COMPLETE    | [COMPLETE, COMPLETE, COMPLETE, COMPLETE]           || [PENDING, PENDING, PENDING, PENDING]
        NOT_STARTED | [NOT_STARTED, NOT_STARTED, NOT_STARTED, NOT_STARTED] || [PENDING, PENDING, PENDING, PENDING]
        COMPLETE    | [NOT_STARTED, NOT_STARTED, NO_MISSION, NO_MISSION] || [PENDING, PENDING, PENDING, PENDING]
    }

    def "reports heard before the upload's id is known count: the ACK and PX4's check may overtake the executor"() {
        given:
        def w = new FeasibilityWatch(3, VehicleState.initial(Autopilot.PX4, VehicleFamily.COPTER).withMissionCurrent(0, 3, NOT_STARTED, 0xA))
        w.heard(NO_ITEM, 3, NOT_STARTED, 0xB)
        w.heard(0, 3, NOT_STARTED, 0xB)
        w.heard(0, 3, NOT_STARTED, 0xB)

        when:
        w.uploaded(0xB)

        then:
        w.verdict() == PENDING

        when:
        w.heard(0, 3, NOT_STARTED, 0xB)

        then:
        w.verdict() == FEASIBLE
    }

    def "the same mission again (id 0xB before and after) is not checked again: its state stands, COMPLETE included: #why"() {
        expect:
        watch([seq, 3, state, 0xB], 0xB, []).verdict() == verdict
        watch([seq, 3, state, 0xB], 0xB, [[seq, 3, state, 0xB]]).verdict() == verdict

        where:
        seq | state       || verdict    | why
        3   | COMPLETE    || FEASIBLE   | 'flown before'
        0   | NOT_STARTED || FEASIBLE   | 'never flown'
        0   | NO_MISSION  || INFEASIBLE | 'found infeasible before'
    }

    def "without ids (the vehicle or the upload names none) a valid state for as many items is all there is: #why"() {
        expect:
        watch([0, 3, COMPLETE, before], uploaded, [[0, total, state, id]]).verdict() == verdict

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
        watch([0, 3, NOT_STARTED, 0], 0xB, [[0, 3, NOT_STARTED, 0xB]]).namesMissions()
        !watch([0, 3, NOT_STARTED, 0], 0xB, [[0, 3, NOT_STARTED, 0]]).namesMissions()
        !watch([0, 3, NOT_STARTED, 0], 0, [[0, 3, NOT_STARTED, 0xB]]).namesMissions()
        watch([0, 3, NOT_STARTED, 0xB], 0xB, []).unchanged()
        !watch([0, 3, NOT_STARTED, 0xA], 0xB, []).unchanged()
        !watch([0, 3, NOT_STARTED, 0], 0, []).unchanged()
    }

    def "what the last report said, for a verdict that did not come"() {
        when:
        def w = watch([2, 3, COMPLETE, 0xA], 0xB, [[NO_ITEM, NO_ITEM, NO_MISSION, 0xB]])

        then: 'PX4 counts no items as UINT16_MAX'
        w.lastTotal() == 0
        w.unchecked()
        w.lastState() == NO_MISSION

        when:
        w.heard(1, 3, NOT_STARTED, 0xB)

        then:
        w.lastTotal() == 3
        !w.unchecked()
    }
}
