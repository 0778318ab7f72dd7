package dolphin.sim

import com.MAVLink.common.msg_gimbal_manager_information
import com.MAVLink.common.msg_camera_information
import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_home_position
import com.MAVLink.enums.CAMERA_CAP_FLAGS
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_RESULT
import spock.lang.Specification

import static dolphin.sim.SimDriver.HOME

/**
 * Asked for CAMERA_INFORMATION, a vehicle answers as ArduPilot does: ACCEPTED, then one message
 * when it has a camera, none when it has not. Fake clock, no sockets.
 */
class SimCameraSpec extends Specification {

    static final int CAMERA_INFORMATION = msg_camera_information.MAVLINK_MSG_ID_CAMERA_INFORMATION

    static SimDriver vehicle(int sysid, SysidSet cameras) {
        new SimDriver(VehicleKind.COPTER, SimOptions.DEFAULT, HOME, 0, new SimEquipment([], cameras), sysid)
    }

    static String text(short[] chars) {
        new String(chars.findAll { it != 0 } as byte[], 'US-ASCII')
    }

    def "a vehicle with a camera: ACCEPTED, then its CAMERA_INFORMATION"() {
        given:
        def d = vehicle(2, SysidSet.of([2, 3]))
        d.run(3)
        int from = d.mark()

        when:
        def ack = d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [CAMERA_INFORMATION])

        then:
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        def info = d.since(from, msg_camera_information)
        info.size() == 1
        text(info[0].vendor_name) == 'Dolphin'
        text(info[0].model_name) == 'SimCam'
        info[0].flags == CAMERA_CAP_FLAGS.CAMERA_CAP_FLAGS_CAPTURE_IMAGE
        info[0].cam_Definition_Uri == ''
        info[0].time_boot_ms == 3000

        and: 'the acknowledgement first'
        d.indexOf(from) { it instanceof msg_command_ack } < d.indexOf(from) { it instanceof msg_camera_information }
    }

    def "a vehicle without a camera: ACCEPTED and nothing more"() {
        given:
        def d = vehicle(1, SysidSet.of([2]))
        int from = d.mark()

        when:
        def ack = d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [CAMERA_INFORMATION])
        d.run(2)

        then:
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.since(from, msg_camera_information).empty
    }

    def "GIMBAL_MANAGER_INFORMATION: ACCEPTED, as ArduPilot answers without a mount, and nothing more"() {
        given:
        def d = vehicle(1, SysidSet.ALL)
        int from = d.mark()

        when:
        def ack = d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [msg_gimbal_manager_information.MAVLINK_MSG_ID_GIMBAL_MANAGER_INFORMATION])
        d.run(2)

        then:
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.since(from, msg_gimbal_manager_information).empty
    }

    def "other requested messages are answered as before; unknown ones FAILED"() {
        given:
        def d = vehicle(1, SysidSet.ALL)
        int from = d.mark()

        expect:
        d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [msg_home_position.MAVLINK_MSG_ID_HOME_POSITION]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.since(from, msg_home_position).size() == 1
        d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [99999]).result == MAV_RESULT.MAV_RESULT_FAILED
        d.since(from, msg_camera_information).empty
    }
}
