package dolphin.sim

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_command_long
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.common.msg_mission_request
import com.MAVLink.common.msg_mission_request_int
import com.MAVLink.common.msg_mission_request_list
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.core.SystemClock
import dolphin.mavlink.codec.Frame
import dolphin.mavlink.codec.FrameWriter
import dolphin.mission.model.MissionItem
import dolphin.testing.FrameListener

import java.util.concurrent.CopyOnWriteArrayList

/**
 * A bare ground station for the simulator's tests: one UDP socket on loopback, our FrameWriter and
 * FrameReader, every message received kept (with the time it came, in clock nanoseconds), and a
 * simulated fleet sending to it. Every wait has a deadline in real seconds.
 */
class RawGroundStation implements AutoCloseable {

    static class Received {
        final long at
        final MAVLinkMessage message

        Received(long at, MAVLinkMessage message) {
            this.at = at
            this.message = message
        }
    }

    final SystemClock clock
    final DatagramSocket socket = new DatagramSocket(0, InetAddress.getLoopbackAddress())
    final List<Received> received = new CopyOnWriteArrayList<>()
    final SimFleet fleet
    private final FrameListener listener
    private final Map<Integer, FrameWriter> writers = [:]

    RawGroundStation(VehicleKind kind = VehicleKind.COPTER, double speedup = 20, SimOptions options = SimOptions.DEFAULT,
                     SimEquipment equipment = SimEquipment.NONE) {
        clock = new SystemClock(speedup)
        listener = new FrameListener(socket, 'raw-gcs', { Frame f, SocketAddress from ->
            if (f.message()) {
                received << new Received(clock.nanoTime(), f.message())
            }
        })
        def config = SimFleet.Config.of(1, kind, new InetSocketAddress(InetAddress.getLoopbackAddress(), socket.localPort))
                .withOptions(options).withEquipment(equipment)
        fleet = new SimFleet(config, clock)
        fleet.start()
    }

    SimVehicle vehicle() { fleet.vehicle(1) }

    /** Sends as ground station (sysid, compid) to the vehicle's port. */
    void send(MAVLinkMessage m, int sysid = 255, int compid = 190) {
        FrameWriter w = writers.computeIfAbsent(sysid * 256 + compid) { new FrameWriter(sysid, compid) }
        byte[] frame = w.write(m)
        socket.send(new DatagramPacket(frame, frame.length, InetAddress.getLoopbackAddress(), fleet.port(1)))
    }

    int mark() { received.size() }

    /** The messages of a type received since {@code from} (an index from mark()). */
    public <T> List<T> since(int from, Class<T> type) {
        new ArrayList<Received>(received).drop(from).collect { it.message }.findAll { type.isInstance(it) } as List<T>
    }

    public <T> T await(int from, Class<T> type, Closure<Boolean> match) {
        await(from, type, 5, match)
    }

    /** Waits for a message of a type, received after {@code from}, that matches; fails after the deadline. */
    public <T> T await(int from, Class<T> type, double seconds = 5, Closure<Boolean> match = { true }) {
        long end = System.nanoTime() + (long) (seconds * 1e9)
        while (System.nanoTime() < end) {
            def hit = since(from, type).find(match)
            if (hit != null) {
                return hit as T
            }
            Thread.sleep(5)
        }
        throw new AssertionError("no ${type.simpleName} within ${seconds} s; got " +
                new ArrayList<Received>(received).drop(from).collect { it.message.class.simpleName }.countBy { it })
    }

    /** The index in received of the first message after {@code from} that matches. */
    int indexOf(int from, Closure<Boolean> match) {
        for (int i = from; i < received.size(); i++) {
            if (match(received[i].message)) {
                return i
            }
        }
        return -1
    }

    def command(int command, List<Number> params = [], double seconds = 5) {
        int from = mark()
        def p = (params + [0] * 7).take(7)
        send(new msg_command_long(target_system: 1, target_component: 1, command: command, param1: p[0], param2: p[1],
                param3: p[2], param4: p[3], param5: p[4], param6: p[5], param7: p[6]))
        await(from, msg_command_ack, seconds) { it.command == command }
    }

    /**
     * Uploads items (seq 0 first) answering each MISSION_REQUEST; returns the final MISSION_ACK type.
     * A request repeated because our answer was slow is answered again, and the vehicle's
     * INVALID_SEQUENCE for the duplicate item is not final: the upload goes on.
     */
    int upload(List<MissionItem> items, double seconds = 10) {
        int from = mark()
        send(new msg_mission_count(target_system: 1, target_component: 1, count: items.size()))
        long end = System.nanoTime() + (long) (seconds * 1e9)
        int seen = from
        while (System.nanoTime() < end) {
            while (seen < received.size()) {
                def m = received[seen++].message
                if (m instanceof msg_mission_request) {
                    send(items[m.seq].toMessage(1, 1))
                } else if (m instanceof msg_mission_ack && m.type != MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE) {
                    return m.type
                }
            }
            Thread.sleep(2)
        }
        throw new AssertionError("upload of ${items.size()} items did not finish within ${seconds} s")
    }

    /** Downloads the stored mission with MISSION_REQUEST_LIST and MISSION_REQUEST_INT. */
    List<MissionItem> download(double seconds = 5) {
        int from = mark()
        send(new msg_mission_request_list(target_system: 1, target_component: 1))
        int count = await(from, msg_mission_count, seconds).count
        (0..<count).collect { int seq ->
            int f = mark()
            send(new msg_mission_request_int(target_system: 1, target_component: 1, seq: seq))
            MissionItem.fromMessage(await(f, msg_mission_item_int, seconds) { it.seq == seq })
        }.tap { send(new msg_mission_ack(target_system: 1, target_component: 1, type: MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED)) }
    }

    /** Waits (real seconds) until the vehicle satisfies the condition. */
    void waitFor(double seconds, String what, Closure<Boolean> condition) {
        long end = System.nanoTime() + (long) (seconds * 1e9)
        while (System.nanoTime() < end) {
            if (condition()) {
                return
            }
            Thread.sleep(10)
        }
        throw new AssertionError("timed out after ${seconds} s waiting for ${what}")
    }

    @Override
    void close() {
        fleet.close()
        listener.close()
    }
}
