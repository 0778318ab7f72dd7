package dolphin.mavlink

import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.minimal.msg_heartbeat
import spock.lang.Specification

/** The autopilot axis: mode tables, how a mode is asked for, and how missions are numbered (docs/px4.md). */
class AutopilotSpec extends Specification {

    def "the heartbeat's autopilot #mav is #autopilot"() {
        expect:
        Autopilot.of(mav) == autopilot

        where:
        mav                                        || autopilot
        MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA  || Autopilot.ARDUPILOT
        MAV_AUTOPILOT.MAV_AUTOPILOT_PX4            || Autopilot.PX4
        MAV_AUTOPILOT.MAV_AUTOPILOT_GENERIC        || Autopilot.OTHER
    }

    def "PX4's custom_mode #hex is #name: main mode in bits 16 to 23, sub mode in 24 to 31"() {
        expect:
        Px4Modes.TABLE.name(custom) == name
        Px4Modes.TABLE.number(name).asLong == custom
        Px4Modes.TABLE.number(name.toLowerCase()).asLong == custom

        where:
        custom     || name
        0x03040000 || 'AUTO.LOITER'
        0x04040000 || 'AUTO.MISSION'
        0x05040000 || 'AUTO.RTL'
        0x06040000 || 'AUTO.LAND'
        0x0a040000 || 'AUTO.VTOL_TAKEOFF'
        0x00030000 || 'POSCTL'
        0x01030000 || 'POSCTL.ORBIT'
        0x00010000 || 'MANUAL'
        hex = String.format('0x%08x', custom)
    }

    def "a mode no table knows is shown by its number"() {
        expect:
        Px4Modes.TABLE.name(0x07040000) == 'mode 117702656'
        !Px4Modes.TABLE.number('AUTO').present
        Autopilot.OTHER.modes(VehicleFamily.OTHER).name(3) == 'mode 3'
    }

    def "DO_SET_MODE asks ArduPilot for the whole custom_mode in param2, PX4 for its main and sub modes in param2 and param3"() {
        expect:
        Autopilot.ARDUPILOT.setModeParams(3) as List == [1f, 3f]
        Autopilot.PX4.setModeParams(Px4Modes.customMode(Px4Modes.MAIN_AUTO, Px4Modes.AUTO_MISSION)) as List == [1f, 4f, 4f]
        Autopilot.PX4.setModeParams(Px4Modes.customMode(Px4Modes.MAIN_POSCTL, 0)) as List == [1f, 3f, 0f]
    }

    def "an ArduPilot mission's seq 0 is its home; PX4's is the first item, which the runtime numbers 1"() {
        expect:
        Autopilot.ARDUPILOT.missionSeq(3) == 3
        Autopilot.ARDUPILOT.vehicleSeq(3) == 3
        Autopilot.PX4.missionSeq(0) == 1
        Autopilot.PX4.vehicleSeq(1) == 0
        Autopilot.ARDUPILOT.homeItem() && !Autopilot.PX4.homeItem()
        Autopilot.ARDUPILOT.missionFtp() && !Autopilot.PX4.missionFtp()
    }

    def "what a vehicle is called names its autopilot and family"() {
        expect:
        Autopilot.ARDUPILOT.label(VehicleFamily.COPTER) == 'ArduCopter'
        Autopilot.ARDUPILOT.label(VehicleFamily.VTOL) == 'ArduPlane VTOL'
        Autopilot.PX4.label(VehicleFamily.COPTER) == 'PX4 multicopter'
        Autopilot.PX4.label(VehicleFamily.PLANE) == 'PX4 fixed-wing'
        Autopilot.OTHER.label(VehicleFamily.OTHER) == 'other'
    }

    def "a PX4 vehicle's MISSION_CURRENT is numbered the runtime's way, its mode named from PX4's table"() {
        given:
        def hb = new msg_heartbeat()
        hb.custom_mode = 0x04040000
        hb.base_mode = 128

        when:
        def s = VehicleState.initial(Autopilot.PX4, VehicleFamily.COPTER).withHeartbeat(hb, 0)
                .withMissionCurrent(0, 5, MISSION_STATE.MISSION_STATE_ACTIVE)

        then:
        s.missionSeq() == 1
        s.missionTotal() == 5
        s.modeName() == 'AUTO.MISSION'
        s.inMode('AUTO.MISSION')
        !s.inMode('AUTO')
        s.flyingMission()
        s.kind() == 'PX4 multicopter'
    }

    def "MISSION_CURRENT's total of 65535 says the vehicle holds no mission"() {
        expect:
        VehicleState.initial(Autopilot.PX4, VehicleFamily.COPTER).withMissionCurrent(0, 65535, MISSION_STATE.MISSION_STATE_NO_MISSION)
                .missionTotal() == 0
    }
}
