package dolphin.mission.flight

import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MISSION_STATE
import dolphin.core.CompletionState
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mission.dsl.MissionDsl
import dolphin.mission.flight.MissionExecutor.FlightState

/**
 * An item the vehicle refuses in flight is an error, never a hang, for every family (ItemRefusals;
 * docs/mavlink.md, "Refused items"): the vehicle warns and passes the item at once without reporting it
 * reached, or starts its mission over without completing it. ArduSub does the first with "Bad alt
 * frame" for any frame but heights relative to home, racing through a whole mission within 0.1 s
 * (docs/decisions.md, "ArduSub behaviour"); ArduCopter, ArduPlane and Rover say "Skipping invalid
 * cmd #N" for a command they cannot verify. The vehicle's words come in the order it sends them;
 * the clock is a ManualClock.
 */
class RefusedItemSpec extends MissionFlights {

    static final int WARNING = MAV_SEVERITY.MAV_SEVERITY_WARNING
    static final int COMPLETE = MISSION_STATE.MISSION_STATE_COMPLETE

    /** Three waypoints (items 1 to 3) the family flies: 20 m up, or 10 m down for a submarine. */
    static MissionTask threeWaypoints(VehicleFamily family) {
        boolean sub = family == VehicleFamily.SUB
        double height = sub ? -10 : 840
        MissionDsl.mission {
            name 'three'
            if (sub) {
                maxDepth 30
            } else {
                allowBelowHome true
            }
            goPos 40.4443, -7.375234, height
            goPos 40.4446, -7.375234, height
            goPos 40.4449, -7.375234, height
        }
    }

    /** A family's vehicle flying the three waypoints: uploaded, armed, started, item 1 under way. */
    MissionExecutor flying(VehicleFamily family) {
        vehicle = new FakeFlightVehicle(clock, '1', family)
        vehicle.ready()
        vehicle.autopilot = true
        def e = launch(threeWaypoints(family))
        stepUntil(FlightState.RUNNING)
        e
    }

    def "#family: a warning and item 2 passed at once without being reached is an ERROR naming the vehicle, the item and its words"() {
        given:
        flying(family)
        vehicle.text('Mission: 1 WP')
        runTo(5)
        vehicle.next(2)

        when: 'the vehicle starts item 2, refuses it and goes on to item 3 in the same update'
        vehicle.text('Mission: 2 WP')
        vehicle.text(refusal, WARNING)
        vehicle.text('Mission: 3 WP')
        vehicle.missionCurrent(3)
        def outcome = runTo(6)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message == "mission three on vehicle 1: vehicle 1 refused item 2 of 3 (NAV_WAYPOINT): '${refusal}'"
        executor.state() == FlightState.ERROR

        where:
        family               | refusal
        VehicleFamily.COPTER | 'Skipping invalid cmd #16'
        VehicleFamily.PLANE  | 'Skipping invalid cmd #16'
        VehicleFamily.ROVER  | 'Skipping invalid cmd #16'
        VehicleFamily.SUB    | 'Bad alt frame'
    }

    def "ArduSub racing through a mission of refused items, COMPLETE in the same second as AUTO, is that ERROR, not DONE"() {
        given: 'the frames of ArduSub SITL given heights above mean sea level (docs/decisions.md)'
        flying(VehicleFamily.SUB)

        when:
        ['Mission: 1 WP', 'Bad alt frame', 'Mission: 2 WP', 'Bad alt frame', 'Mission: 3 WP', 'Bad alt frame'].each {
            vehicle.text(it, it.startsWith('Bad') ? WARNING : MAV_SEVERITY.MAV_SEVERITY_INFO)
        }
        vehicle.missionCurrent(3, COMPLETE)
        def outcome = runTo(1)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message.endsWith("vehicle 1 refused item 1 of 3 (NAV_WAYPOINT): 'Bad alt frame'")
    }

    def "#family: a mission that starts over at item 1 before completing is an ERROR, with the warning heard"() {
        given:
        flying(family)
        vehicle.next(2)
        runTo(20)
        vehicle.next(3)
        runTo(40)

        when:
        vehicle.text('Some warning', WARNING)
        vehicle.missionCurrent(1)
        def outcome = runTo(41)

        then:
        outcome.type == CompletionState.Type.ERROR
        outcome.message == 'mission three on vehicle 1: vehicle 1 started its mission over at item 1 before finishing' +
                " item 3 of 3 (NAV_WAYPOINT), after 'Some warning': it is not flying the mission as uploaded"

        where:
        family << [VehicleFamily.COPTER, VehicleFamily.PLANE, VehicleFamily.ROVER, VehicleFamily.SUB]
    }

    def "#family: a warning during a long leg whose MISSION_ITEM_REACHED is lost is no refusal: the mission ends DONE"() {
        given:
        flying(family)
        vehicle.missionCurrent(1)
        runTo(1)

        when: 'a warning at 2 s, item 2 current at 30 s with no MISSION_ITEM_REACHED for item 1, then the end'
        runTo(2)
        vehicle.text('EKF variance', WARNING)
        runTo(30)
        vehicle.missionCurrent(2)
        runTo(60)
        vehicle.next(3)
        runTo(90)
        vehicle.reached(3)
        vehicle.missionCurrent(3, COMPLETE)
        def outcome = runTo(91)

        then:
        outcome.type == CompletionState.Type.DONE

        where:
        family << [VehicleFamily.COPTER, VehicleFamily.PLANE, VehicleFamily.ROVER, VehicleFamily.SUB]
    }

    def "ArduCopter restarting its mission as it disarms after the landing that ends it is its end, not a restart"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        launch(hop())
        stepUntil(FlightState.RUNNING)
        vehicle.landedState(com.MAVLink.enums.MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR)
        vehicle.at(0, 20)
        vehicle.next(2)
        runTo(10)
        vehicle.next(3)
        vehicle.at(0, 0)
        runTo(20)

        when: 'MISSION_CURRENT back on the take-off, on the ground but still armed, before the disarmed HEARTBEAT, as SITL sends them'
        vehicle.missionCurrent(1)
        runTo(21)
        vehicle.landAndDisarm()
        def outcome = runTo(22)

        then:
        outcome.type == CompletionState.Type.DONE
    }

    def "going back to an item by jumpToItem is ours, not a restart; the jump's repeat flies to DONE"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        launch(MissionDsl.mission {
            name 'three'
            allowBelowHome true
            goPos 40.4443, -7.375234, 840
            goPos 40.4446, -7.375234, 840
            jumpToItem 1, 1
            goPos 40.4449, -7.375234, 840
        })
        stepUntil(FlightState.RUNNING)
        vehicle.next(2)
        runTo(10)

        when: 'item 2 reached: the executor jumps to 1, which the vehicle shows, then flies on'
        vehicle.next(3)
        runTo(11)
        vehicle.missionCurrent(1)
        runTo(12)
        vehicle.next(2)
        runTo(20)
        vehicle.next(3)
        runTo(30)
        vehicle.reached(3)
        vehicle.missionCurrent(3, COMPLETE)
        def outcome = runTo(31)

        then:
        messages.contains('mission three on vehicle 1: jump to item 1')
        outcome.type == CompletionState.Type.DONE
    }

    def "a DO_JUMP in the mission makes going back the mission's own"() {
        given:
        vehicle.ready()
        vehicle.autopilot = true
        def items = MissionDsl.mission {
            goPos 40.4443, -7.375234, 840
            goPos 40.4446, -7.375234, 840
        }.mission().items(FakeFlightVehicle.HOME)
        def jump = dolphin.mission.model.MissionItem.command(3, com.MAVLink.enums.MAV_CMD.MAV_CMD_DO_JUMP, 1, 2, 0, 0)
        launch(new MissionTask(dolphin.mission.model.RawItemPoint.mission('looped', items + [jump])))
        stepUntil(FlightState.RUNNING)
        vehicle.next(2)
        runTo(10)

        when:
        vehicle.missionCurrent(1)
        def outcome = runTo(11)

        then:
        outcome.type != CompletionState.Type.ERROR
        !executor.completed
    }

    def "a warning before the mission starts (arming) is not the first item's complaint"() {
        given:
        vehicle = new FakeFlightVehicle(clock, '1', VehicleFamily.ROVER)
        vehicle.ready()
        vehicle.autopilot = true
        launch(threeWaypoints(VehicleFamily.ROVER))
        vehicle.text('PreArm: Hardware safety switch', WARNING)
        stepUntil(FlightState.RUNNING)

        when: 'item 1 flown and reached late, MISSION_CURRENT 2 at once'
        vehicle.text('Mission: 1 WP')
        vehicle.text('Mission: 2 WP')
        vehicle.missionCurrent(2)
        def outcome = runTo(1)

        then:
        outcome.type != CompletionState.Type.ERROR
        !executor.completed
    }
}
