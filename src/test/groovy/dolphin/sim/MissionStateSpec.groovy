package dolphin.sim

import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_set_current
import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MISSION_STATE
import dolphin.mission.model.MissionItem
import spock.lang.Specification

import static dolphin.sim.MissionProtocolSpec.rel
import static dolphin.sim.SimDriver.HOME

/**
 * Where a simulated vehicle's mission stands, as AP_Mission keeps it and MISSION_CURRENT reports it
 * (docs/mavlink.md, "The simulated fleet and real ArduPilot"): set by DO_SET_MISSION_CURRENT with and
 * without its reset flag, stopped by leaving AUTO, kept by an upload.
 */
class MissionStateSpec extends Specification {

    static final int NOT_STARTED = MISSION_STATE.MISSION_STATE_NOT_STARTED
    static final int ACTIVE = MISSION_STATE.MISSION_STATE_ACTIVE

    static final List<MissionItem> MISSION = [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                                              rel(1, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 0, 0, 0, 0, 5),
                                              rel(2, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10),
                                              rel(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 0, 10),
                                              rel(4, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 30, 10)]

    SimDriver d = new SimDriver(VehicleKind.COPTER)

    def setup() {
        assert d.upload(MISSION) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.tick()
    }

    /** The last MISSION_CURRENT sent since {@code from}, as [seq, total, state]. */
    List<Integer> current(int from) {
        d.since(from, msg_mission_current).last().with { [it.seq, it.total, it.mission_state as int] }
    }

    def "after an upload the mission has not started and no item is current"() {
        expect:
        current(0) == [0, 4, NOT_STARTED]
    }

    def "DO_SET_MISSION_CURRENT without the reset flag leaves the mission NOT_STARTED at the item's nav item, to run from there"() {
        when:
        int from = d.mark()
        def ack = d.command(MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, [1, 0])
        d.tick()

        then: 'the first nav item from item 1 on is the take-off'
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        current(from) == [2, 4, NOT_STARTED]
        d.texts(from).empty
    }

    def "with the reset flag it runs at once, outside AUTO: ACTIVE at the nav item, its items started"() {
        given:
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED

        when:
        int from = d.mark()
        def ack = d.command(MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, [1, 1])
        d.tick()

        then: 'the copter stays on the ground in GUIDED'
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        current(from) == [2, 4, ACTIVE]
        d.texts(from) == ['Mission: 1 ChangeSpeed', 'Mission: 2 Takeoff']
        d.vehicle.landedState() == 1

        when: 'AUTO and MISSION_START'
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        d.command(MAV_CMD.MAV_CMD_MISSION_START)
        d.runUntil(30, 'the first waypoint current') { d.vehicle.missionCurrent() == 3 }

        then:
        d.vehicle.missionState() == ACTIVE
    }

    def "a seq not stored is DENIED; MISSION_SET_CURRENT is answered at once with the seq asked for"() {
        expect:
        d.command(MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, [5, 0]).result == MAV_RESULT.MAV_RESULT_DENIED

        when:
        int from = d.mark()
        d.handle(new msg_mission_set_current(target_system: 1, target_component: 1, seq: 1))

        then: 'before any tick: seq 1 as asked, though the current nav item is 2'
        current(from) == [1, 4, NOT_STARTED]
        d.vehicle.missionCurrent() == 2
    }

    def "leaving AUTO stops the mission (NOT_STARTED, never PAUSED) where it was; AUTO again resumes it there"() {
        given:
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        d.arm()
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        d.command(MAV_CMD.MAV_CMD_MISSION_START)
        d.runUntil(30, 'the first waypoint current') { d.vehicle.missionCurrent() == 3 }

        when:
        int from = d.mark()
        d.setMode(COPTER_MODE.COPTER_MODE_LOITER)
        d.run(1)

        then:
        current(from) == [3, 4, NOT_STARTED]

        when:
        from = d.mark()
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        d.run(1)

        then:
        current(from) == [3, 4, ACTIVE]
    }

    def "an upload keeps the mission's place, even past the end of a shorter mission; AUTO then starts that mission from the top"() {
        given:
        d.command(MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, [4, 0])

        when:
        int from = d.mark()
        assert d.upload(MISSION.take(3)) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.tick()

        then:
        current(from) == [4, 2, NOT_STARTED]

        when:
        from = d.mark()
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        d.run(1)

        then: 'its DO item run again, its take-off current'
        current(from) == [2, 2, ACTIVE]
        d.texts(from) == ['Mission: 1 ChangeSpeed', 'Mission: 2 Takeoff']
    }
}
