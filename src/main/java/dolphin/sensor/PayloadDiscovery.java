package dolphin.sensor;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_camera_information;
import com.MAVLink.common.msg_gimbal_manager_information;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.minimal.msg_heartbeat;
import dolphin.core.Payload;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkNode;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Learns a vehicle's payloads from what it announces (docs/sensors.md, "Payloads"): components that
 * send their own heartbeat (a MAVLink camera, gimbal or companion computer), and the CAMERA_INFORMATION
 * and GIMBAL_MANAGER_INFORMATION the autopilot sends when asked with MAV_CMD_REQUEST_MESSAGE, on its
 * first message and twice more while unanswered. ArduPilot accepts that request whatever it carries
 * and then sends one CAMERA_INFORMATION per configured camera, nothing without one, nor while it is
 * still starting up: a copter SITL asked at its first heartbeat said nothing of its camera
 * (docs/decisions.md).
 */
final class PayloadDiscovery {

    static final String CAMERA = "Camera";
    static final String GIMBAL = "Gimbal";

    private static final Map<Integer, String> COMPONENT_KINDS = Map.of(
            MAV_TYPE.MAV_TYPE_CAMERA, CAMERA,
            MAV_TYPE.MAV_TYPE_GIMBAL, GIMBAL,
            MAV_TYPE.MAV_TYPE_ONBOARD_CONTROLLER, "Companion",
            MAV_TYPE.MAV_TYPE_PARACHUTE, "Parachute",
            MAV_TYPE.MAV_TYPE_ADSB, "ADSB");

    /** When to ask again, after the first question, while the answer has not come. */
    static final List<Duration> ASK_AGAIN = List.of(Duration.ofSeconds(5), Duration.ofSeconds(20));

    /** How questions reach a vehicle and wait: the communications, or a test's fake. */
    interface Questions {
        /** Sends MAV_CMD_REQUEST_MESSAGE for the message to the vehicle's autopilot. */
        void request(MAVLinkNode node, int messageId);

        /** Runs the action after the delay, on the communications thread. */
        void later(Duration delay, Runnable action);
    }

    private final Questions questions;
    private final Set<MAVLinkNode> asked = ConcurrentHashMap.newKeySet();

    PayloadDiscovery(Questions questions) {
        this.questions = questions;
    }

    /** Questions over the communications; the sender queues requests with the same command id to a vehicle. */
    static PayloadDiscovery over(MAVLinkCommunications comms) {
        return new PayloadDiscovery(new Questions() {
            @Override
            public void request(MAVLinkNode node, int messageId) {
                comms.command(node, MAV_CMD.MAV_CMD_REQUEST_MESSAGE, messageId);
            }

            @Override
            public void later(Duration delay, Runnable action) {
                comms.schedule(delay, action);
            }
        });
    }

    void message(MAVLinkNode node, int component, MAVLinkMessage m) {
        if (component == node.getAutopilotCompid() && asked.add(node)) {
            ask(node, 0);
        }
        if (m instanceof msg_heartbeat hb && component != node.getAutopilotCompid()) {
            String kind = COMPONENT_KINDS.get((int) hb.type);
            if (kind != null) {
                node.addPayload(new Payload.Component(kind, Map.of("component", component)));
            }
        } else if (m instanceof msg_camera_information c) {
            node.addPayload(new Payload.Component(CAMERA, Map.of("component", component,
                    "vendor", text(c.vendor_name), "model", text(c.model_name))));
        } else if (m instanceof msg_gimbal_manager_information g) {
            node.addPayload(new Payload.Component(GIMBAL, Map.of("component", component, "device", (int) g.gimbal_device_id)));
        }
    }

    /** Asks for what is not known yet, then again after the next delay of {@link #ASK_AGAIN}. */
    private void ask(MAVLinkNode node, int round) {
        boolean camera = !node.getPayload().has(CAMERA);
        boolean gimbal = !node.getPayload().has(GIMBAL);
        if (camera) {
            questions.request(node, msg_camera_information.MAVLINK_MSG_ID_CAMERA_INFORMATION);
        }
        if (gimbal) {
            questions.request(node, msg_gimbal_manager_information.MAVLINK_MSG_ID_GIMBAL_MANAGER_INFORMATION);
        }
        if ((camera || gimbal) && round < ASK_AGAIN.size()) {
            questions.later(ASK_AGAIN.get(round), () -> ask(node, round + 1));
        }
    }

    /** A reading's name is a payload too: a vehicle that sends SMOKE carries a smoke sensor. */
    void readingNamed(MAVLinkNode node, String name) {
        if (!node.getPayload().has(name)) {
            node.addPayload(Payload.Component.named(name));
        }
    }

    private static String text(short[] bytes) {
        StringBuilder b = new StringBuilder();
        for (short c : bytes) {
            if (c == 0) {
                break;
            }
            b.append((char) (c & 0xff));
        }
        return new String(b.toString().getBytes(StandardCharsets.ISO_8859_1), StandardCharsets.UTF_8);
    }
}
