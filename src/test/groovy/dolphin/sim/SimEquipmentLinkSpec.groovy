package dolphin.sim

import com.MAVLink.common.msg_camera_information
import com.MAVLink.common.msg_named_value_float
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_RESULT
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.sim.SimDriver.HOME

/**
 * Over the fleet's UDP link, as a ground station sees them: readings and the camera's
 * description come from the vehicle's autopilot (its system id, component 1), as ArduPilot's do.
 */
@Timeout(30)
class SimEquipmentLinkSpec extends Specification {

    @AutoCleanup
    RawGroundStation gcs = new RawGroundStation(VehicleKind.COPTER, 20, SimOptions.DEFAULT,
            new SimEquipment([new SimSensor('SMOKE', new PlumeField(HOME, 60, 100, 0))], SysidSet.ALL))

    def "a reading and the camera's information arrive from system 1, component 1"() {
        when:
        def reading = gcs.await(0, msg_named_value_float)
        int from = gcs.mark()
        def ack = gcs.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [msg_camera_information.MAVLINK_MSG_ID_CAMERA_INFORMATION])
        def info = gcs.await(from, msg_camera_information)

        then:
        reading.name == 'SMOKE'
        Math.abs(reading.value - 100) < 1e-3
        [reading.sysid, reading.compid] == [1, 1]
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        [info.sysid, info.compid] == [1, 1]
    }
}
