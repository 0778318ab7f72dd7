package dolphin.mavlink;

import com.MAVLink.ardupilotmega.msg_ekf_status_report;
import com.MAVLink.common.msg_extended_sys_state;
import com.MAVLink.common.msg_home_position;
import com.MAVLink.common.msg_battery_status;
import com.MAVLink.common.msg_mission_current;
import com.MAVLink.standard.msg_global_position_int;
import com.MAVLink.common.msg_sys_status;
import com.MAVLink.common.msg_request_data_stream;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_DATA_STREAM;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Asks each vehicle for the telemetry the runtime reads, because ArduCopter sends none unless asked
 * (docs/decisions.md, "ArduPilot behaviour we rely on"): MAV_CMD_SET_MESSAGE_INTERVAL per message,
 * falling back to REQUEST_DATA_STREAM when a vehicle refuses it, and asking again when a stream
 * falls silent.
 * Runs on the communications thread.
 */
final class TelemetryRequests {


    private static final long MIN_SILENCE = 3_000_000_000L;

    private static final class Stream {
        final long intervalNanos;
        /**
         * A message only some autopilots send (EKF_STATUS_REPORT is ArduPilot's): a refusal does not
         * switch the vehicle to REQUEST_DATA_STREAM, and it is asked for again only once it was seen.
         */
        final boolean optional;
        long lastSeen;
        boolean seen;
        long lastRequest;

        Stream(long intervalNanos, boolean optional) {
            this.intervalNanos = intervalNanos;
            this.optional = optional;
        }

        long silenceLimit() {
            return Math.max(MIN_SILENCE, 5 * intervalNanos);
        }
    }

    private static final class Vehicle {
        final Map<Integer, Stream> streams = new LinkedHashMap<>();
        boolean fallback;
    }

    private final MAVLinkCommunications comms;
    private final long fastNanos;
    private final Map<MAVLinkNode, Vehicle> vehicles = new LinkedHashMap<>();
    private final Map<String, AtomicInteger> rerequests = new ConcurrentHashMap<>();

    TelemetryRequests(MAVLinkCommunications comms, double hz) {
        this.comms = comms;
        this.fastNanos = (long) (1e9 / hz);
    }

    void discovered(MAVLinkNode node, long now) {
        Vehicle v = new Vehicle();
        for (int id : new int[] {msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS,
                msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT, msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT}) {
            v.streams.put(id, new Stream(fastNanos, false));
        }
        for (int id : new int[] {msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE,
                msg_battery_status.MAVLINK_MSG_ID_BATTERY_STATUS, msg_home_position.MAVLINK_MSG_ID_HOME_POSITION}) {
            v.streams.put(id, new Stream(1_000_000_000L, false));
        }
        v.streams.put(msg_ekf_status_report.MAVLINK_MSG_ID_EKF_STATUS_REPORT, new Stream(1_000_000_000L, true));
        vehicles.put(node, v);
        v.streams.forEach((id, s) -> request(node, v, id, s, now));
    }

    void seen(MAVLinkNode node, int msgid, long now) {
        Vehicle v = vehicles.get(node);
        Stream s = v == null ? null : v.streams.get(msgid);
        if (s != null) {
            s.lastSeen = now;
            s.seen = true;
        }
    }

    /** Asks again for the streams that fell silent (vehicles that are lost are left alone). */
    void check(long now) {
        vehicles.forEach((node, v) -> {
            if (!node.isConnected()) {
                return;
            }
            v.streams.forEach((id, s) -> {
                if ((!s.optional || s.seen) && now - Math.max(s.lastSeen, s.lastRequest) > s.silenceLimit()) {
                    rerequests.computeIfAbsent(node.getId(), k -> new AtomicInteger()).incrementAndGet();
                    request(node, v, id, s, now);
                }
            });
        });
    }

    /** How many times streams of a vehicle were asked for again after falling silent. */
    int rerequests(String nodeId) {
        AtomicInteger n = rerequests.get(nodeId);
        return n == null ? 0 : n.get();
    }

    private void request(MAVLinkNode node, Vehicle v, int msgid, Stream s, long now) {
        s.lastRequest = now;
        if (v.fallback) {
            requestDataStreams(node, s.intervalNanos);
            return;
        }
        comms.commandOnCommsThread(node, MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL, msgid, s.intervalNanos / 1000f)
                .thenAccept(r -> {
                    if (!r.accepted() && !v.fallback && !s.optional) {
                        v.fallback = true;
                        requestDataStreams(node, fastNanos);
                    }
                });
    }

    private void requestDataStreams(MAVLinkNode node, long intervalNanos) {
        int hz = (int) Math.max(1, Math.round(1e9 / intervalNanos));
        for (int stream : new int[] {MAV_DATA_STREAM.MAV_DATA_STREAM_EXTENDED_STATUS, MAV_DATA_STREAM.MAV_DATA_STREAM_POSITION,
                MAV_DATA_STREAM.MAV_DATA_STREAM_EXTRA3}) {
            msg_request_data_stream m = new msg_request_data_stream();
            m.target_system = (short) node.getMavLinkId();
            m.target_component = (short) node.getAutopilotCompid();
            m.req_stream_id = (short) stream;
            m.req_message_rate = hz;
            m.start_stop = 1;
            comms.sendOnCommsThread(node, m);
        }
    }
}
