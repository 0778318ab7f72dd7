package dolphin.mission.transfer

import dolphin.mission.model.MissionItem
import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.common.msg_mission_request
import com.MAVLink.common.msg_mission_request_int
import com.MAVLink.common.msg_mission_request_list
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.mavlink.codec.FrameReader
import dolphin.mavlink.codec.FrameWriter

/**
 * A scripted vehicle on a raw UDP socket: heartbeats every 50 ms (real time), and the vehicle side
 * of the mission protocol as ArduPilot does it (MISSION_REQUEST during upload, INVALID_SEQUENCE for
 * an item out of order, COUNT truncates), with faults injected by name:
 * countLost, itemLost (item faultSeq, first time), duplicateRequests, reorderedRequests, errorAck
 * (result errorAck at item faultSeq), noAck, outOfRange, silentAt (item faultSeq), requestInt,
 * listLost, dlItemLost (first request for item faultSeq).
 */
class FakeMissionVehicle implements AutoCloseable {
    final int sysid
    final DatagramSocket socket = new DatagramSocket(0, InetAddress.loopbackAddress)
    final InetSocketAddress gcs
    final FrameWriter writer
    final FrameReader reader = new FrameReader()
    /** Written by the vehicle's thread while tests read it: iterating a copy-on-write list never throws. */
    final List<String> log = new java.util.concurrent.CopyOnWriteArrayList<String>()
    volatile List<MissionItem> stored = []
    Set<String> faults = [] as Set
    int faultSeq = -1
    int errorAck = -1
    volatile boolean silent
    volatile boolean running = true
    private final Set<String> once = [] as Set
    private MissionItem[] incoming
    private int expected = -1
    private Thread thread

    FakeMissionVehicle(int sysid, int gcsPort) {
        this.sysid = sysid
        this.gcs = new InetSocketAddress('127.0.0.1', gcsPort)
        this.writer = new FrameWriter(sysid, 1)
        socket.soTimeout = 5
    }

    FakeMissionVehicle start() {
        thread = Thread.start("fake vehicle $sysid") { loop() }
        this
    }

    List<String> received(String prefix) { log.findAll { it.startsWith('in ' + prefix) } }

    private void loop() {
        byte[] buf = new byte[2048]
        long nextHb = 0
        while (running) {
            if (!silent && System.nanoTime() >= nextHb) {
                out(new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA,
                        custom_mode: 4), false)
                nextHb = System.nanoTime() + 50_000_000L
            }
            try {
                def p = new DatagramPacket(buf, buf.length)
                socket.receive(p)
                reader.feed(p.data, 0, p.length) { f -> if (f.message() != null) handle(f.message()) }
                reader.endOfPacket { f -> if (f.message() != null) handle(f.message()) }
            } catch (SocketTimeoutException ignored) {
            } catch (IOException closed) {
                return
            }
        }
    }

    private boolean first(String what) { once.add(what) }

    private void out(MAVLinkMessage m, boolean logged = true) {
        if (silent) {
            return
        }
        if (logged) {
            log << "out ${describe(m)}".toString()
        }
        byte[] f = writer.write(m)
        socket.send(new DatagramPacket(f, f.length, gcs))
    }

    private static String describe(MAVLinkMessage m) {
        switch (m) {
            case msg_mission_count: return "COUNT ${m.count}"
            case msg_mission_request: return "REQUEST ${m.seq}"
            case msg_mission_request_int: return "REQUEST_INT ${m.seq}"
            case msg_mission_item_int: return "ITEM_INT ${m.seq}"
            case msg_mission_ack: return "ACK ${m.type}"
            case msg_mission_request_list: return 'REQUEST_LIST'
            default: return m.class.simpleName
        }
    }

    private void request(int seq) {
        def r = faults.contains('requestInt') ? new msg_mission_request_int(seq: seq) : new msg_mission_request(seq: seq)
        r.target_system = 208
        r.target_component = 190
        out(r)
        if (faults.contains('duplicateRequests')) {
            out(r)
        }
    }

    private void ack(int type) {
        out(new msg_mission_ack(target_system: 208, target_component: 190, type: type))
    }

    private void handle(MAVLinkMessage m) {
        if (silent) {
            return
        }
        log << "in ${describe(m)}".toString()
        if (m instanceof msg_mission_count) {
            if (faults.contains('countLost') && first('count')) {
                return
            }
            incoming = new MissionItem[m.count]
            stored = []                                  // ArduPilot truncates on COUNT
            expected = 0
            if (m.count == 0) {
                ack(MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED)
            } else {
                request(0)
            }
        } else if (m instanceof msg_mission_item_int) {
            int seq = m.seq
            if (faults.contains('itemLost') && seq == faultSeq && first('item')) {
                return                                   // lost on the way: the vehicle does not re-request
            }
            if (expected < 0) {
                return
            }
            if (seq != expected) {
                ack(MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE)
                return
            }
            if (faults.contains('silentAt') && seq == faultSeq) {
                silent = true
                return
            }
            if (faults.contains('errorAck') && seq == faultSeq) {
                expected = -1
                ack(errorAck)
                return
            }
            incoming[seq] = MissionItem.fromMessage(m)
            expected++
            if (faults.contains('outOfRange') && seq == 1) {
                request(incoming.length + 2)
            } else if (expected == incoming.length) {
                stored = incoming as List
                expected = -1
                if (!faults.contains('noAck')) {
                    ack(MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED)
                }
            } else if (faults.contains('reorderedRequests') && seq >= 1) {
                request(expected)
                request(seq)                             // a stale request arriving late
            } else {
                request(expected)
            }
        } else if (m instanceof msg_mission_request_list) {
            if (faults.contains('listLost') && first('list')) {
                return
            }
            out(new msg_mission_count(target_system: 208, target_component: 190, count: stored.size()))
        } else if (m instanceof msg_mission_request_int) {
            if (faults.contains('dlItemLost') && m.seq == faultSeq && first('dl')) {
                return
            }
            def item = stored[m.seq].toMessage(208, 190)
            out(item)
        }
    }

    @Override
    void close() {
        running = false
        thread?.join(1000)
        socket.close()
    }
}
