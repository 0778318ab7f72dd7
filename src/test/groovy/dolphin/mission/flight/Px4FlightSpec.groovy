package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MISSION_STATE
import dolphin.core.CompletionState
import dolphin.core.Position
import dolphin.mavlink.Autopilot
import dolphin.mavlink.VehicleFamily
import dolphin.mission.dsl.MissionDsl
import dolphin.mission.flight.MissionExecutor.FlightState
import dolphin.mission.model.MissionType
import java.time.Duration

/**
 * How the executor flies a PX4 vehicle (Px4Rules; docs/px4.md): its modes asked for as main and sub
 * modes, nothing asked until its feasibility check shows the mission NOT_STARTED, started from the
 * first item by MISSION_START alone, items numbered from 0 on the vehicle, AUTO.RTL when cut short,
 * and the commands and frames PX4 takes. A FakeFlightVehicle on a ManualClock.
 */
class Px4FlightSpec extends MissionFlights {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    FakeFlightVehicle px4(VehicleFamily family = VehicleFamily.COPTER) {
        def v = new FakeFlightVehicle(clock, '1', family, Autopilot.PX4)
        v.ready()
        v.autopilot = true
        v
    }

    /** A PX4 vehicle holding mission 0xA, valid and never flown (NOT_STARTED), the hop launched on it, its upload naming 0xB: at ARM. */
    void armingNewMission() {
        vehicle = px4()
        vehicle.state = vehicle.state.withMissionCurrent(0, 3, MISSION_STATE.MISSION_STATE_NOT_STARTED, 0xA)
        vehicle.missionId = 0xA
        vehicle.uploadId = 0xB
        launch(hop())
        stepUntil(FlightState.ARM)
    }

    def "a PX4 copter: armed in the mode it is in, then AUTO.MISSION asked as main mode 4, sub mode 4, and MISSION_START; no DO_SET_MISSION_CURRENT"() {
        given:
        vehicle = px4()

        when:
        launch(hop())
        stepUntil(FlightState.RUNNING)

        then:
        vehicle.commands*.text == ['ARM', 'DO_SET_MODE AUTO.MISSION', 'MISSION_START']
        vehicle.commands[1].params as List == [1f, 4f, 4f]
        vehicle.state.inMode('AUTO.MISSION')
    }

    def "items reached and current are numbered from 0 on the vehicle, from 1 in the flight's lines; the landing ends it disarmed"() {
        given:
        vehicle = px4()
        launch(hop())
        stepUntil(FlightState.RUNNING)

        when: 'the vehicle reports its seq 1 reached and seq 2 current: items 2 and 3, the landing'
        vehicle.next(3)
        runTo(10)

        then:
        messages.contains('mission hop on vehicle 1: item 2 of 3 reached')

        when:
        vehicle.landAndDisarm()

        then:
        runTo(30).type == CompletionState.Type.DONE
    }

    def "the last MISSION_ITEM_REACHED of an earlier mission, which PX4 repeats for 10 s, is not this one's"() {
        given:
        vehicle = px4()
        launch(hop())
        stepUntil(FlightState.RUNNING)
        vehicle.missionCurrent(1)

        when: 'the earlier mission\'s item 3 (its seq 2), while this one flies its first item'
        vehicle.reached(3)
        runTo(2)

        then:
        !messages.any { it.contains('reached') }

        when:
        vehicle.next(2)
        runTo(3)

        then:
        messages.last() == 'mission hop on vehicle 1: item 1 of 3 reached'
    }

    def "nothing is asked of a PX4 vehicle until it finds the mission feasible; one it refuses fails with what it said since the upload, unarmed (#ids)"() {
        given:
        vehicle = px4()
        vehicle.feasible = false
        vehicle.uploadId = uploadId
        vehicle.text('Preflight Fail: an earlier complaint', MAV_SEVERITY.MAV_SEVERITY_CRITICAL)
        clock.advance(Duration.ofSeconds(1))
        launch(hop())
        stepUntil(FlightState.ARM)

        when: 'its verdict: no mission; a vehicle that names missions gets 2 s to say why'
        vehicle.checked()
        def waiting = runTo(2.5)

        then:
        waiting.type == CompletionState.Type.IN_PROGRESS
        vehicle.commands.empty

        when:
        vehicle.text('Geofence violation for waypoint 3\t', MAV_SEVERITY.MAV_SEVERITY_CRITICAL)
        def outcome = runTo(3)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message == "mission hop on vehicle 1: vehicle 1 found the mission infeasible: 'Geofence violation for waypoint 3'"
        vehicle.commands.empty

        where:
        uploadId || ids
        0        || 'a vehicle that names no missions'
        0xB      || 'a vehicle that names its missions'
    }

    def "a PX4 vehicle still in AUTO.MISSION after a flight says a new mission ACTIVE once it holds it, not COMPLETE"() {
        given:
        vehicle = px4()
        vehicle.feasible = false
        launch(hop())
        stepUntil(FlightState.ARM)

        when: 'the earlier flight\'s COMPLETE, for as many items'
        vehicle.missionCurrent(3, MISSION_STATE.MISSION_STATE_COMPLETE)
        runTo(2)

        then:
        vehicle.commands.empty

        when:
        vehicle.missionCurrent(3, MISSION_STATE.MISSION_STATE_ACTIVE)
        runTo(3)

        then:
        vehicle.commands*.text == ['ARM', 'DO_SET_MODE AUTO.MISSION', 'MISSION_START']
    }

    def "a PX4 vehicle that names its missions: neither the earlier flight's COMPLETE under the new id nor a sensor's fault is its verdict; its check is"() {
        given: 'the vehicle flew mission 0xA; the upload gives 0xB'
        vehicle = px4()
        vehicle.state = vehicle.state.withMissionCurrent(2, 3, MISSION_STATE.MISSION_STATE_COMPLETE, 0xA)
        vehicle.missionId = 0xA
        vehicle.uploadId = 0xB
        launch(hop())
        stepUntil(FlightState.ARM)

        when: 'MISSION_CURRENT names 0xB with no current item and the earlier COMPLETE; a sensor fails'
        vehicle.text('MAG #0 failed: TIMEOUT!', MAV_SEVERITY.MAV_SEVERITY_CRITICAL)
        def waiting = runTo(2)

        then:
        vehicle.state.missionId() == 0xB
        vehicle.state.missionSeq() == -1
        waiting.type == CompletionState.Type.IN_PROGRESS
        vehicle.commands.empty

        when:
        vehicle.checked()
        runTo(3)

        then:
        vehicle.commands*.text == ['ARM', 'DO_SET_MODE AUTO.MISSION', 'MISSION_START']
    }

    def "the first report of a new mission's check may carry the earlier mission's state: a refused mission is not armed on it"() {
        given:
        armingNewMission()

        when: 'the check gives the current item; PX4 has not worked the state out again yet: the earlier NOT_STARTED'
        vehicle.missionCurrent(1, MISSION_STATE.MISSION_STATE_NOT_STARTED)
        def waiting = runTo(2)

        then:
        waiting.type == CompletionState.Type.IN_PROGRESS
        vehicle.commands.empty

        when: 'worked out: NO_MISSION, and why'
        vehicle.missionCurrent(1, MISSION_STATE.MISSION_STATE_NO_MISSION)
        vehicle.text('Geofence violation for waypoint 3\t', MAV_SEVERITY.MAV_SEVERITY_CRITICAL)
        def outcome = runTo(3)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message == "mission hop on vehicle 1: vehicle 1 found the mission infeasible: 'Geofence violation for waypoint 3'"
        vehicle.commands.empty
    }

    def "a new mission's state the same as the earlier mission's is its verdict from the third checked report, a second later"() {
        given:
        armingNewMission()

        when: 'the report the check triggers, then PX4\'s reports at 1 Hz'
        vehicle.missionCurrent(1, MISSION_STATE.MISSION_STATE_NOT_STARTED)
        runTo(1)
        vehicle.missionCurrent(1, MISSION_STATE.MISSION_STATE_NOT_STARTED)
        runTo(2)

        then:
        vehicle.commands.empty

        when:
        vehicle.missionCurrent(1, MISSION_STATE.MISSION_STATE_NOT_STARTED)
        runTo(3)

        then:
        vehicle.commands*.text == ['ARM', 'DO_SET_MODE AUTO.MISSION', 'MISSION_START']
    }

    def "a PX4 vehicle given the very mission it flew keeps it COMPLETE: that is its verdict, and MISSION_START from the first item flies it again"() {
        given:
        vehicle = px4()
        vehicle.state = vehicle.state.withMissionCurrent(2, 3, MISSION_STATE.MISSION_STATE_COMPLETE, 0xB)
        vehicle.missionId = 0xB
        vehicle.uploadId = 0xB

        when:
        launch(hop())
        stepUntil(FlightState.RUNNING)

        then:
        vehicle.commands*.text == ['ARM', 'DO_SET_MODE AUTO.MISSION', 'MISSION_START']
        vehicle.commands[2].params[0] == 0f
    }

    def "refused without a word, a new mission fails 2 s after the verdict; the same mission found infeasible before fails at once"() {
        given:
        vehicle = px4()
        vehicle.feasible = false
        vehicle.uploadId = 0xB
        vehicle.missionId = before
        if (before == 0xB) {
            vehicle.state = vehicle.state.withMissionCurrent(0, 3, MISSION_STATE.MISSION_STATE_NO_MISSION, 0xB)
        }
        launch(hop())
        stepUntil(FlightState.ARM)
        if (before != 0xB) {
            vehicle.checked()
        }

        when:
        def outcome = runTo(3)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message == 'mission hop on vehicle 1: vehicle 1 found the mission infeasible' + why
        Math.abs(now() - at) < 0.15
        vehicle.commands.empty

        where:
        before || at  | why
        0xA    || 2.0 | ' (MISSION_CURRENT: no mission) and said nothing of why'
        0xB    || 0.1 | ' when it was given it before: it holds this same mission, and does not check it again'
    }

    def "a mission MISSION_CURRENT never says feasible fails after 10 s, unarmed"() {
        given:
        vehicle = px4()
        vehicle.feasible = false
        launch(hop())
        stepUntil(FlightState.ARM)

        when:
        def outcome = runTo(12)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message.endsWith('vehicle 1 did not find the mission feasible within 10 s: MISSION_CURRENT still says no mission')
        vehicle.commands.empty
    }

    def "a vehicle that never shows its check of a new mission fails after 10 s with what MISSION_CURRENT and the vehicle said, unarmed"() {
        given: '0xB is named with no current item and the earlier NOT_STARTED from then on'
        armingNewMission()
        vehicle.text('Geofence violation for waypoint 3\t', MAV_SEVERITY.MAV_SEVERITY_CRITICAL)

        when:
        def waiting = runTo(9)
        (1..3).each { vehicle.uncheckedCurrent() }
        def outcome = runTo(12)

        then:
        waiting.type == CompletionState.Type.IN_PROGRESS
        outcome.type == CompletionState.Type.ERROR
        outcome.message.endsWith("vehicle 1 did not find the mission feasible within 10 s: MISSION_CURRENT still names no current item"
                + " and says NOT_STARTED: the vehicle has not shown its check; the vehicle said 'Geofence violation for waypoint 3'")
        vehicle.commands.empty
    }

    def "cut short, a PX4 vehicle returns in AUTO.RTL"() {
        given:
        vehicle = px4()
        launch(hop())
        stepUntil(FlightState.RUNNING)
        int before = vehicle.commands.size()

        when:
        executor.stop()

        then:
        vehicle.commands.drop(before)*.text == ['DO_SET_MODE AUTO.RTL']
        vehicle.commands.last().params as List == [1f, 4f, 5f]
    }

    def "commands without a position go in MAV_FRAME_MISSION; a PX4 VTOL's take-off and landing become VTOL items"() {
        given:
        vehicle = px4(family)
        def task = MissionDsl.mission {
            name 'hop'
            home HOME
            takeOff HOME.atHeight(850)
            speed 8
            move 100, 0
            returnHomeAndLand()
        }

        when:
        launch(task)
        stepUntil(FlightState.RUNNING)
        def uploaded = vehicle.stored[MissionType.MISSION]

        then:
        uploaded.drop(1)*.command == commands
        uploaded.find { it.command == MAV_CMD.MAV_CMD_DO_CHANGE_SPEED }.frame == MAV_FRAME.MAV_FRAME_MISSION
        uploaded.findAll { it.command != MAV_CMD.MAV_CMD_DO_CHANGE_SPEED }.every { it.frame != MAV_FRAME.MAV_FRAME_MISSION }

        where:
        family               || commands
        VehicleFamily.COPTER || [MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LAND]
        VehicleFamily.VTOL   || [MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_VTOL_LAND]
    }

    def "#what is refused before anything is uploaded: #message"() {
        given:
        vehicle = px4()

        when:
        launch(task)
        def outcome = runTo(1)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message == "mission ${task.mission().id} on vehicle 1: ${message}"
        vehicle.transfers.empty

        where:
        what                   | task  || message
        'a loiter turn'        | MissionDsl.mission { name 'turns'; takeOff HOME.atHeight(850); loiterTurns 40.4446, -7.375234, 850, 2 } || 'item 2 (NAV_LOITER_TURNS) cannot be flown by vehicle 1 (PX4 multicopter): PX4\'s missions do not fly this command: loiter for a time (NAV_LOITER_TIME) instead'
    }
}
