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
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Learns a vehicle's payloads from what it announces (docs/sensors.md, "Payloads"): components that
 * send their own heartbeat (a MAVLink camera, gimbal or companion computer), and the CAMERA_INFORMATION
 * and GIMBAL_MANAGER_INFORMATION the autopilot sends when asked with MAV_CMD_REQUEST_MESSAGE, once, on
 * its first message. ArduPilot accepts that request whatever it carries and then sends one
 * CAMERA_INFORMATION per configured camera, nothing without one (docs/decisions.md).
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

    private final MAVLinkCommunications comms;
    private final Set<MAVLinkNode> asked = ConcurrentHashMap.newKeySet();

    PayloadDiscovery(MAVLinkCommunications comms) {
        this.comms = comms;
    }

    void message(MAVLinkNode node, int component, MAVLinkMessage m) {
        if (component == node.getAutopilotCompid() && asked.add(node)) {
            // one request after the other: a COMMAND_ACK names only the command, so the sender queues them anyway
            comms.command(node, MAV_CMD.MAV_CMD_REQUEST_MESSAGE, msg_camera_information.MAVLINK_MSG_ID_CAMERA_INFORMATION)
                    .whenComplete((r, e) -> comms.command(node, MAV_CMD.MAV_CMD_REQUEST_MESSAGE,
                            msg_gimbal_manager_information.MAVLINK_MSG_ID_GIMBAL_MANAGER_INFORMATION));
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
