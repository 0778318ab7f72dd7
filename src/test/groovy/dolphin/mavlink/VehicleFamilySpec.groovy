package dolphin.mavlink

import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MAV_VTOL_STATE
import spock.lang.Specification

/** Which family a heartbeat and an EXTENDED_SYS_STATE make a vehicle (docs/vtol.md, "Telling a QuadPlane"). */
class VehicleFamilySpec extends Specification {

    def "MAV_TYPE #type of ArduPilot is #family, running #firmware's firmware"() {
        expect:
        VehicleFamily.of(type, MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA) == family
        family.firmware() == firmware

        where:
        type                               || family               | firmware
        MAV_TYPE.MAV_TYPE_QUADROTOR        || VehicleFamily.COPTER | VehicleFamily.COPTER
        MAV_TYPE.MAV_TYPE_HELICOPTER       || VehicleFamily.HELI   | VehicleFamily.COPTER
        MAV_TYPE.MAV_TYPE_FIXED_WING       || VehicleFamily.PLANE  | VehicleFamily.PLANE
        MAV_TYPE.MAV_TYPE_VTOL_QUADROTOR   || VehicleFamily.VTOL   | VehicleFamily.PLANE
        MAV_TYPE.MAV_TYPE_VTOL_TILTROTOR   || VehicleFamily.VTOL   | VehicleFamily.PLANE
        MAV_TYPE.MAV_TYPE_SUBMARINE        || VehicleFamily.SUB    | VehicleFamily.SUB
    }

    def "PX4's MAV_TYPE #type is #family; any type of another autopilot is OTHER"() {
        expect:
        VehicleFamily.of(type, MAV_AUTOPILOT.MAV_AUTOPILOT_PX4) == family
        VehicleFamily.of(type, MAV_AUTOPILOT.MAV_AUTOPILOT_GENERIC) == VehicleFamily.OTHER

        where:
        type                               || family
        MAV_TYPE.MAV_TYPE_QUADROTOR        || VehicleFamily.COPTER
        MAV_TYPE.MAV_TYPE_FIXED_WING       || VehicleFamily.PLANE
        MAV_TYPE.MAV_TYPE_VTOL_RESERVED2   || VehicleFamily.VTOL
        MAV_TYPE.MAV_TYPE_GROUND_ROVER     || VehicleFamily.ROVER
    }

    def "an ArduPlane whose VTOL state is #vtolState is #family; no other family changes with it"() {
        expect:
        VehicleFamily.PLANE.withVtolState(vtolState) == family
        VehicleFamily.COPTER.withVtolState(vtolState) == VehicleFamily.COPTER
        VehicleFamily.VTOL.withVtolState(vtolState) == VehicleFamily.VTOL

        where:
        vtolState                                     || family
        MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED       || VehicleFamily.PLANE
        MAV_VTOL_STATE.MAV_VTOL_STATE_MC              || VehicleFamily.VTOL
        MAV_VTOL_STATE.MAV_VTOL_STATE_FW              || VehicleFamily.VTOL
        MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_FW || VehicleFamily.VTOL
    }

    def "a VTOL and a helicopter have their firmware's modes on ArduPilot"() {
        expect:
        Autopilot.ARDUPILOT.modes(VehicleFamily.VTOL).number('QRTL').asLong == 21
        Autopilot.ARDUPILOT.modes(VehicleFamily.VTOL) == Autopilot.ARDUPILOT.modes(VehicleFamily.PLANE)
        Autopilot.ARDUPILOT.modes(VehicleFamily.HELI) == Autopilot.ARDUPILOT.modes(VehicleFamily.COPTER)
    }

    def "an ArduPlane's VTOL state makes it a VTOL; a PX4 plane's does not (PX4 says VTOL in its heartbeat)"() {
        expect:
        VehicleState.initial(Autopilot.ARDUPILOT, VehicleFamily.PLANE).withExtendedState(1, MAV_VTOL_STATE.MAV_VTOL_STATE_FW).family() == VehicleFamily.VTOL
        VehicleState.initial(Autopilot.PX4, VehicleFamily.PLANE).withExtendedState(1, MAV_VTOL_STATE.MAV_VTOL_STATE_FW).family() == VehicleFamily.PLANE
    }

    def "only an ArduPlane not yet heard in EXTENDED_SYS_STATE may still turn out a VTOL"() {
        given:
        def arduPlane = VehicleState.initial(Autopilot.ARDUPILOT, VehicleFamily.PLANE)

        expect:
        arduPlane.mayBeVtol()
        !arduPlane.withExtendedState(MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND, MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED).mayBeVtol()
        !VehicleState.initial(Autopilot.PX4, VehicleFamily.PLANE).mayBeVtol()
        !VehicleState.initial(Autopilot.ARDUPILOT, VehicleFamily.COPTER).mayBeVtol()
        !VehicleState.initial(Autopilot.OTHER, VehicleFamily.PLANE).mayBeVtol()
    }
}
