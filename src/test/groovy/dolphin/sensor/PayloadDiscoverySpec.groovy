package dolphin.sensor

import com.MAVLink.common.msg_camera_information
import com.MAVLink.common.msg_gimbal_manager_information
import com.MAVLink.common.msg_sys_status
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.ManualClock
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import java.time.Duration
import spock.lang.Specification

/**
 * When the ground station asks a vehicle for its camera and gimbal, with fake questions on a manual
 * clock: at its first message, then again 5 s and 25 s later while unanswered, never once answered;
 * a component's heartbeat answers without a question.
 */
class PayloadDiscoverySpec extends Specification {

    static final int CAMERA = msg_camera_information.MAVLINK_MSG_ID_CAMERA_INFORMATION
    static final int GIMBAL = msg_gimbal_manager_information.MAVLINK_MSG_ID_GIMBAL_MANAGER_INFORMATION

    ManualClock clock = new ManualClock()
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock),
            null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)
    List<List> asked = []
    PayloadDiscovery discovery = new PayloadDiscovery(new PayloadDiscovery.Questions() {
        void request(MAVLinkNode n, int messageId) { asked << [clock.seconds(), messageId] }

        void later(Duration delay, Runnable action) { clock.schedule(delay, action) }
    })

    def "a vehicle that never answers is asked three times, at its first message, 5 s and 25 s later, then no more"() {
        when:
        discovery.message(node, 1, new msg_sys_status())
        discovery.message(node, 1, new msg_sys_status())
        clock.advance(Duration.ofSeconds(60))

        then:
        asked == [[0d, CAMERA], [0d, GIMBAL], [5d, CAMERA], [5d, GIMBAL], [25d, CAMERA], [25d, GIMBAL]]
    }

    def "an answer ends the questions about what it answers"() {
        when: 'the camera answers the second question'
        discovery.message(node, 1, new msg_sys_status())
        clock.advance(Duration.ofSeconds(5))
        discovery.message(node, 1, new msg_camera_information())
        clock.advance(Duration.ofSeconds(60))

        then:
        asked == [[0d, CAMERA], [0d, GIMBAL], [5d, CAMERA], [5d, GIMBAL], [25d, GIMBAL]]
        node.payload.has('Camera')
    }

    def "a component's own heartbeat is a payload without a question; messages from other components ask nothing"() {
        when:
        discovery.message(node, 100, new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_CAMERA as short))
        discovery.message(node, 154, new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_GIMBAL as short))

        then:
        asked.isEmpty()
        node.payload.names() == ['Camera', 'Gimbal']

        when: 'the autopilot speaks: both are known, nothing is asked'
        discovery.message(node, 1, new msg_sys_status())
        clock.advance(Duration.ofSeconds(60))

        then:
        asked.isEmpty()
    }
}
