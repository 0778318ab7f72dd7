package dolphin.mavlink

import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_command_long
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.mavlink.codec.Frame
import dolphin.mavlink.codec.FrameWriter
import dolphin.mavlink.link.LinkUrl
import dolphin.testing.FrameListener
import java.util.concurrent.CopyOnWriteArrayList
import spock.lang.Specification
import spock.lang.Timeout

/**
 * `dolphin run --forward`: a viewer (QGroundControl, MAVProxy) on a real UDP socket sees the
 * vehicles' own frames, and its commands reach the vehicle they target and are answered to it.
 */
@Timeout(30)
class ForwarderSpec extends Specification {

    /** A viewer on loopback: it collects every frame it receives and sends as system 255. */
    static class Viewer implements AutoCloseable {
        final DatagramSocket socket = new DatagramSocket(0, InetAddress.loopbackAddress)
        final List<Frame> frames = new CopyOnWriteArrayList<>()
        final FrameWriter writer = new FrameWriter(255, 190)
        volatile SocketAddress relay
        private final FrameListener listener = new FrameListener(socket, 'viewer', { Frame f, SocketAddress from ->
            relay = from
            frames << f
        })

        void send(com.MAVLink.Messages.MAVLinkMessage m) {
            byte[] b = writer.write(m)
            socket.send(new DatagramPacket(b, b.length, relay))
        }

        @Override
        void close() {
            listener.close()
        }
    }

    FleetHarness h = new FleetHarness()
    Viewer viewer = new Viewer()
    Forwarder forwarder

    def setup() {
        forwarder = new Forwarder(h.comms, [LinkUrl.parse("udpout:127.0.0.1:${viewer.socket.localPort}")])
        forwarder.start()
        h.fleet(2)
    }

    def cleanup() {
        forwarder?.close()
        viewer?.close()
        h?.close()
    }

    def "the viewer receives every vehicle's frames unchanged, with the vehicle's own system id"() {
        expect:
        h.eventually {
            assert viewer.frames.findAll { it.msgid() == msg_heartbeat.MAVLINK_MSG_ID_HEARTBEAT }*.sysid().toSet() == [1, 2] as Set
        }
        viewer.frames.every { it.sysid() in [1, 2] }
        h.eventually {
            assert forwarder.framesToViewers() >= viewer.frames.size()
            assert forwarder.framesToViewers() <= h.comms.framesIn()
        }
    }

    def "a viewer's command goes to the vehicle it targets only, and the answer comes back to the viewer"() {
        given:
        h.eventually { assert viewer.relay != null && h.comms.nodes().size() == 2 }

        when:
        viewer.send(new msg_command_long(target_system: 2, target_component: 1, command: MAV_CMD.MAV_CMD_GET_HOME_POSITION))

        then:
        h.eventually {
            def acks = viewer.frames.findAll { it.msgid() == msg_command_ack.MAVLINK_MSG_ID_COMMAND_ACK }
                    .findAll { (it.message() as msg_command_ack).target_system == 255 }
            assert acks*.sysid() == [2]
            assert (acks[0].message() as msg_command_ack).command == MAV_CMD.MAV_CMD_GET_HOME_POSITION
            assert (acks[0].message() as msg_command_ack).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        }
        forwarder.framesFromViewers() == 1
    }

    def "a frame that targets no system, like the viewer's heartbeat, goes to every vehicle"() {
        given:
        h.eventually { assert viewer.relay != null && h.comms.nodes().size() == 2 }

        when:
        viewer.send(new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_GCS, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_INVALID, mavlink_version: 3))

        then:
        h.eventually { assert forwarder.framesFromViewers() == 2 }
    }

    def "a viewer link that cannot be opened is an error that names it"() {
        given:
        def taken = new DatagramSocket(0, InetAddress.loopbackAddress)

        when:
        new Forwarder(h.comms, [LinkUrl.parse("udpin:127.0.0.1:${taken.localPort}")]).start()

        then:
        def e = thrown(IOException)
        e.message.startsWith("--forward udpin:127.0.0.1:${taken.localPort}: cannot listen")

        cleanup:
        taken?.close()
    }
}
