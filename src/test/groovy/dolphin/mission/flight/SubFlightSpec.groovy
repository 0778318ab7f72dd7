package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MISSION_STATE
import dolphin.core.CompletionState
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mission.dsl.MissionDsl
import dolphin.mission.flight.MissionExecutor.FlightState
import dolphin.mission.model.MissionType

/**
 * How the executor flies an ArduSub vehicle (FlightRules.Sub; docs/underwater.md): depths as heights
 * relative to home, the only frame ArduSub flies; armed in MANUAL, started by AUTO, done at COMPLETE
 * holding its depth; SURFACE when cut short; an underwater mission for a submarine and only for one;
 * what ArduSub cannot fly refused before the upload. A FakeFlightVehicle on a ManualClock.
 */
class SubFlightSpec extends MissionFlights {

    static final Position COMPORTA = Position.fromDegrees(38.43462, -8.86118, 0)

    static MissionTask dive() {
        MissionDsl.mission {
            name 'dive'
            maxDepth 20
            goPos 38.43490, -8.86118, 0
            dive 10
            move 30, 0
            surface()
        }
    }

    FakeFlightVehicle sub() {
        def v = new FakeFlightVehicle(clock, '1', VehicleFamily.SUB)
        v.ready()
        v.state = v.state.withHome(COMPORTA.atHeight(-0.06))
        v
    }

    def "a sub's items go up relative to home, depths as negative heights; it arms in MANUAL and starts with AUTO; COMPLETE is DONE"() {
        given:
        vehicle = sub()
        vehicle.autopilot = true

        when:
        launch(dive())
        stepUntil(FlightState.RUNNING)
        def uploaded = vehicle.stored[MissionType.MISSION]

        then: 'home as it is; every other item in GLOBAL_RELATIVE_ALT_INT, z = minus the depth below the surface (sea level)'
        uploaded[0].frame == MAV_FRAME.MAV_FRAME_GLOBAL_INT
        uploaded.drop(1)*.frame.every { it == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT }
        uploaded.drop(1)*.z == [0f, -10f, -10f, 0f]
        uploaded.drop(1)*.command == [MAV_CMD.MAV_CMD_NAV_WAYPOINT] * 3 + [MAV_CMD.MAV_CMD_NAV_LAND]
        vehicle.commands*.text == ['DO_SET_MODE MANUAL', 'ARM', 'DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO']

        when: 'the items reached, the surfacing last, and COMPLETE; ArduSub stays armed in AUTO'
        (2..4).each { vehicle.next(it); runTo(it * 30) }
        vehicle.reached(4)
        vehicle.missionCurrent(4, MISSION_STATE.MISSION_STATE_COMPLETE)

        then:
        runTo(121).type == CompletionState.Type.DONE
    }

    def "cut short, a sub rises to the surface (SURFACE): it has no RTL"() {
        given:
        vehicle = sub()
        vehicle.autopilot = true
        launch(dive())
        stepUntil(FlightState.RUNNING)
        int before = vehicle.commands.size()

        when:
        executor.stop()

        then:
        vehicle.commands.drop(before)*.text == ['DO_SET_MODE SURFACE']
        messages.last() == 'mission dive on vehicle 1: cut short: SURFACE'
    }

    def "#what is an ERROR before anything is uploaded: #message"() {
        given:
        vehicle = family == VehicleFamily.SUB ? sub() : new FakeFlightVehicle(clock, '1', family)
        vehicle.ready()
        vehicle.autopilot = true

        when:
        launch(task)
        def outcome = runTo(1)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message == "mission ${task.mission().id} on vehicle 1: ${message}"
        vehicle.transfers.empty

        where:
        what                                    | family               | task                                                    || message
        'a mission in the air for a sub'        | VehicleFamily.SUB    | hop()                                                   || "vehicle 1 (ArduSub) goes under water: its mission must say how deep it may go, 'maxDepth METRES' (docs/underwater.md)"
        'an underwater mission for a copter'    | VehicleFamily.COPTER | dive()                                                  || 'an underwater mission (maxDepth) for vehicle 1 (ArduCopter), which does not dive'
        'an underwater mission for a boat'      | VehicleFamily.ROVER  | dive()                                                  || 'an underwater mission (maxDepth) for vehicle 1 (Rover), which does not dive'
        'a take-off for a sub'                  | VehicleFamily.SUB    | MissionDsl.mission { name 'up'; maxDepth 5; takeOff COMPORTA } || 'item 1 (NAV_TAKEOFF) cannot be flown by vehicle 1 (ArduSub): a submarine does not take off (ArduSub ignores NAV_TAKEOFF): dive instead'
        'a command ArduSub ignores'             | VehicleFamily.SUB    | MissionDsl.mission { name 'cam'; maxDepth 5; goPos COMPORTA; capturePhoto() } || 'item 2 (IMAGE_START_CAPTURE) cannot be flown by vehicle 1 (ArduSub): ArduSub ignores this command'
    }
}
