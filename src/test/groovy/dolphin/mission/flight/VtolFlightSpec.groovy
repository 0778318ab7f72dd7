package dolphin.mission.flight

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_VTOL_STATE
import dolphin.core.CompletionState
import dolphin.core.Position
import dolphin.mavlink.VehicleFamily
import dolphin.mission.dsl.MissionDsl
import dolphin.mission.flight.MissionExecutor.FlightState
import dolphin.mission.model.MissionType

import static dolphin.mission.flight.FakeFlightVehicle.HOME

/**
 * A QuadPlane and a traditional helicopter flown by the executor (docs/vtol.md), on a manual clock:
 * what they receive, how they are armed and started, how they end and are cut short.
 */
class VtolFlightSpec extends MissionFlights {

    /** ArduPlane SITL's quadplane.parm: 25 m/s cruise, 2 m/s² deceleration, so a 156 m stopping distance. */
    static final Map<String, Double> QUADPLANE = [AIRSPEED_CRUISE: 25d, TECS_LAND_ARSPD: -1d, Q_TRANS_DECEL: 2d, Q_OPTIONS: 0d,
                                                  WP_RADIUS: 90d]

    FakeFlightVehicle quadplane() {
        vehicle = new FakeFlightVehicle(clock, '1', VehicleFamily.VTOL)
        vehicle.parameters = new HashMap<>(QUADPLANE)
        vehicle.ready()
        vehicle.autopilot = true
        vehicle
    }

    /** The commands after the mission's DO_SET_HOME. */
    List<String> flightCommands() {
        vehicle.commands*.text.findAll { !it.startsWith('DO_SET_HOME') }
    }

    /** Takes off to 30 m, flies 400 m north and back towards home, and lands there. */
    static MissionTask survey(double lastNorth) {
        MissionDsl.mission {
            name 'survey'
            home 40.444233, -7.375234, 820
            takeOff HOME.atHeight(850)
            goPos HOME.displace(400, 0, -40)
            goPos HOME.displace(lastNorth, 0, -40)
            returnHomeAndLand()
        }
    }

    def "a QuadPlane's take-off and landing go vertical; the landing 60 m after a waypoint gets an approach leg, 426 m to 156 m out"() {
        given:
        quadplane()

        when:
        launch(survey(60))
        stepUntil(FlightState.RUNNING)
        def items = vehicle.stored[MissionType.MISSION]

        then: 'its parameters read, then the take-off a climb of 30 m above where it stands'
        vehicle.log.findAll { it.contains('PARAM_REQUEST_READ') }*.substring(4) ==
                QUADPLANE.keySet().collect { 'PARAM_REQUEST_READ ' + it }
        items*.command() == [MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, MAV_CMD.MAV_CMD_NAV_WAYPOINT,
                             MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_WAYPOINT,
                             MAV_CMD.MAV_CMD_NAV_VTOL_LAND]
        items*.seq() == 0..6
        items[1].frame() == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
        items[1].z() == 30f

        and: 'the approach: on the side it comes from, at the waypoint height, from the stopping distance plus three WP_RADIUS to the stopping distance'
        Math.abs(HOME.horizontalDistanceTo(items[4].position()) - 426.25) < 0.5
        Math.abs(HOME.horizontalDistanceTo(items[5].position()) - 156.25) < 0.5
        [4, 5].every { HOME.displacementTo(items[it].position())[0] > 156 && items[it].z() == items[3].z() }
        items[6].param1() == 0f
        HOME.horizontalDistanceTo(items[6].position()) < 0.01
        messages.containsAll(said('survey', ['item 4 added: NAV_WAYPOINT, the approach to the landing after it',
                                             'item 5 added: NAV_WAYPOINT, the approach to the landing after it']))

        and: 'armed in AUTO with its first item current, which starts it; no MISSION_START'
        flightCommands() == ['DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO', 'ARM', 'DO_SET_MODE AUTO']
    }

    def "a landing as far from its waypoint as the stopping distance and WP_RADIUS, or after an item that is no waypoint, is kept as written"() {
        given:
        quadplane()

        when:
        launch(task)
        stepUntil(FlightState.RUNNING)

        then:
        vehicle.stored[MissionType.MISSION]*.command() == commands

        where:
        task << [survey(247), MissionDsl.mission {
            name 'hover'
            home 40.444233, -7.375234, 820
            takeOff HOME.atHeight(850)
            returnHomeAndLand()
        }]
        commands << [[16, 84, 16, 16, 85], [16, 84, 85]]
    }

    def "a QuadPlane is DONE when, its landing current, it is on the ground and disarmed, still in AUTO; then it leaves AUTO"() {
        given:
        quadplane()
        launch(survey(400))
        stepUntil(FlightState.RUNNING)

        when:
        vehicle.landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR)
        vehicle.at(100, 30)
        vehicle.next(2)
        runTo(10)
        vehicle.next(4)
        def landing = runTo(20)
        vehicle.landAndDisarm()
        def end = runTo(21)

        then: 'then QLOITER ends the landing sequence of ArduPlane, which would keep it from arming'
        landing == CompletionState.IN_PROGRESS
        end == CompletionState.DONE
        vehicle.commands*.text.last() == 'DO_SET_MODE QLOITER'
    }

    def "a QuadPlane cut short lands vertically at home: QRTL"() {
        given:
        quadplane()
        launch(survey(400))
        stepUntil(FlightState.RUNNING)

        when:
        executor.stop()

        then:
        vehicle.commands*.text.last() == 'DO_SET_MODE QRTL'
        messages.last() == said('survey', ['cut short: QRTL'])[0]
    }

    def "a runway take-off is refused before upload on a QuadPlane whose Q_OPTIONS do not allow it, and flown as written on one that does"() {
        given:
        quadplane()
        vehicle.parameters.Q_OPTIONS = options
        def task = MissionDsl.mission {
            name 'runway'
            home 40.444233, -7.375234, 820
            takeOffOnRunway HOME.atHeight(850)
            goPos HOME.displace(400, 0, -40)
            returnHomeAndLandVertically()
        }

        when:
        launch(task)
        def end = runTo(1)

        then:
        (end == CompletionState.IN_PROGRESS) == allowed
        allowed ? vehicle.stored[MissionType.MISSION]*.command() == [16, 22, 16, 85]
                : end.message.endsWith('item 1 (NAV_TAKEOFF) is to be flown on a runway, but the vehicle flies it vertically:'
                        + ' its Q_OPTIONS (0) do not allow fixed-wing take-offs (bit 1)')
        allowed || vehicle.transfers.empty

        where:
        options || allowed
        0d      || false
        2d      || true
    }

    def "a way the vehicle does not fly is refused before upload: a plane without VTOL motors vertically, a copter on a runway"() {
        given:
        vehicle = new FakeFlightVehicle(clock, '1', family)
        vehicle.ready()
        vehicle.autopilot = true

        when:
        launch(task)
        def end = runTo(1)

        then:
        end.message.endsWith(error)
        vehicle.transfers.empty

        where:
        family               | task                                                                                   || error
        VehicleFamily.PLANE  | MissionDsl.mission { name 'v'; takeOffVertically HOME.atHeight(850) }                || 'item 1 (NAV_TAKEOFF) is to be flown vertically, which vehicle 1 (ArduPlane) does not do'
        VehicleFamily.COPTER | MissionDsl.mission { name 'r'; home 40.444233, -7.375234, 820; takeOff HOME.atHeight(850); returnHomeAndLandOnRunway() } || 'item 2 (NAV_LAND) is to be flown on a runway, which vehicle 1 (ArduCopter) does not do'
    }

    def "a QuadPlane that does not give its AIRSPEED_CRUISE gets an error naming the parameter, and nothing is uploaded"() {
        given:
        quadplane()
        vehicle.parameters.remove('AIRSPEED_CRUISE')

        when:
        launch(survey(60))
        def end = runTo(1)

        then:
        end.message.endsWith('vehicle 1 (ArduPlane VTOL) cannot fly the mission: the vehicle did not give its AIRSPEED_CRUISE'
                + ' parameter, which its take-offs and landings are planned with (ArduPlane before 4.5 named it TRIM_ARSPD_CM,'
                + ' which is not read)')
        vehicle.transfers.empty
    }

    def "an ArduPlane is flown as a plane once its EXTENDED_SYS_STATE says no VTOL, as a QuadPlane once it says one, and after 5 s without one as a plane"() {
        given:
        vehicle = new FakeFlightVehicle(clock, '1', VehicleFamily.PLANE)
        vehicle.parameters = new HashMap<>(QUADPLANE)
        vehicle.state = vehicle.state.withExtendedState(MAV_LANDED_STATE.MAV_LANDED_STATE_UNDEFINED, MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED)
        vehicle.ready()
        vehicle.autopilot = true

        when:
        launch(survey(400))
        runTo(1)

        then: 'waiting'
        vehicle.transfers.empty
        messages == ['waiting for vehicle 1: its EXTENDED_SYS_STATE, which tells a QuadPlane from a plane']

        when:
        if (vtolState != null) {
            vehicle.state = vehicle.state.withExtendedState(MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND, vtolState)
        }
        runTo(seconds)

        then:
        vehicle.stored[MissionType.MISSION][1].command() == takeoff

        where:
        vtolState                             | seconds || takeoff
        MAV_VTOL_STATE.MAV_VTOL_STATE_MC      | 1.2     || MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF
        MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED | 1.2   || MAV_CMD.MAV_CMD_NAV_TAKEOFF
        null                                  | 5.2     || MAV_CMD.MAV_CMD_NAV_TAKEOFF
    }

    def "a helicopter: interlock off to arm, on once armed, AUTO asked again while its rotor runs up, interlock off after landing"() {
        given:
        vehicle = new FakeFlightVehicle(clock, '1', VehicleFamily.HELI)
        vehicle.ready()
        vehicle.autopilot = true
        int autoRefusals = 0
        vehicle.answers['DO_SET_MODE AUTO'] = { FakeFlightVehicle.Command c ->
            vehicle.answer(c, autoRefusals++ < 2 ? MAV_RESULT.MAV_RESULT_FAILED : MAV_RESULT.MAV_RESULT_ACCEPTED)
        }
        launch(hop())

        when:
        runTo(10)

        then:
        executor.state() == FlightState.RUNNING
        vehicle.commands*.text == ['DO_AUX_FUNCTION 32 0', 'DO_SET_MODE GUIDED', 'ARM', 'DO_AUX_FUNCTION 32 2',
                                   'DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO', 'DO_SET_MODE AUTO', 'DO_SET_MODE AUTO', 'MISSION_START']

        when:
        vehicle.landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR)
        vehicle.at(20, 20)
        vehicle.next(3)
        runTo(12)
        vehicle.landAndDisarm()
        def end = runTo(13)

        then:
        end == CompletionState.DONE
        vehicle.commands*.text.last() == 'DO_AUX_FUNCTION 32 0'
        messages.takeRight(2) == said(['motor interlock off (DO_AUX_FUNCTION 32 low)', 'done'])
    }

    def "a helicopter already flying gets no interlock off (autorotation) when it takes a new mission"() {
        given:
        vehicle = new FakeFlightVehicle(clock, '1', VehicleFamily.HELI)
        vehicle.ready()
        vehicle.heartbeat(true, 'LOITER')
        vehicle.landedState(MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR)
        vehicle.autopilot = true

        when:
        launch(hop())
        runTo(1)

        then:
        executor.state() == FlightState.RUNNING
        vehicle.commands*.text == ['DO_SET_MODE GUIDED', 'ARM', 'DO_AUX_FUNCTION 32 2', 'DO_SET_MISSION_CURRENT 1', 'DO_SET_MODE AUTO',
                                   'MISSION_START']
    }

    def "a VTOL take-off read from a file at a height above sea level is sent as its height above home; a plane refuses VTOL items"() {
        given:
        vehicle = family == VehicleFamily.VTOL ? quadplane() : new FakeFlightVehicle(clock, '1', family)
        vehicle.ready()
        vehicle.autopilot = true
        def items = dolphin.mission.file.MissionFile.read('''QGC WPL 110
0\t1\t0\t16\t0\t0\t0\t0\t40.444233\t-7.375234\t820\t1
1\t0\t0\t84\t0\t0\t0\t0\t40.444233\t-7.375234\t850\t1
2\t0\t3\t16\t0\t0\t0\t0\t40.448\t-7.375234\t40\t1
3\t0\t3\t85\t0\t0\t0\t0\t40.444233\t-7.375234\t0\t1
''').mission()

        when:
        launch(new MissionTask(dolphin.mission.model.RawItemPoint.mission('file', items)))
        def end = runTo(1)

        then:
        family == VehicleFamily.VTOL ? vehicle.stored[MissionType.MISSION][1].z() == 30f && vehicle.stored[MissionType.MISSION][1].frame()
                == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
                : end.message.endsWith('item 1 (NAV_VTOL_TAKEOFF) cannot be flown by vehicle 1 (ArduPlane): ArduPlane flies VTOL items'
                        + ' only on a QuadPlane (Q_ENABLE, and rebooted since)')

        where:
        family << [VehicleFamily.VTOL, VehicleFamily.PLANE]
    }

    def "an approach waypoint outside the mission's fence is refused before upload; inside it, the mission flies"() {
        given:
        quadplane()
        def task = MissionDsl.mission {
            name 'fenced'
            home 40.444233, -7.375234, 820
            fence {
                inclusion circle(HOME, radius)
            }
            takeOff HOME.atHeight(850)
            goPos HOME.displace(300, 0, -40)
            goPos HOME.displace(60, 0, -40)
            returnHomeAndLand()
        }

        when:
        launch(task)
        def end = runTo(1)

        then:
        refused ? end.message.endsWith("item 4, the approach waypoint the landing after it needs, is outside the mission's fence"
                + ' (inclusion circle of 400 m): write the approach in the mission (docs/vtol.md)')
                : end == CompletionState.IN_PROGRESS && vehicle.stored[MissionType.MISSION].size() == 7
        refused == vehicle.transfers.empty

        where:
        radius || refused
        400    || true
        500    || false
    }

    def "a helicopter's interlock goes off once it has a position estimate, not at boot, when ArduCopter has not read its RC yet"() {
        given:
        vehicle = new FakeFlightVehicle(clock, '1', VehicleFamily.HELI)
        vehicle.autopilot = true

        when:
        launch(hop())
        runTo(1)

        then:
        vehicle.commands.empty
        messages == ['waiting for vehicle 1: no position estimate yet']

        when:
        vehicle.ready()
        runTo(2)

        then:
        vehicle.commands*.text.first() == 'DO_AUX_FUNCTION 32 0'
    }
}
