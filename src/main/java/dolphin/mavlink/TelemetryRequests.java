package dolphin.mavlink;

import com.MAVLink.standard.msg_global_position_int;
import com.MAVLink.common.msg_request_data_stream;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_DATA_STREAM;
import dolphin.mavlink.link.Link;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Asks each vehicle for the telemetry the runtime reads, because ArduCopter sends none unless asked
 * (docs/decisions.md, "ArduPilot behaviour we rely on"): MAV_CMD_SET_MESSAGE_INTERVAL per message,
 * falling back to REQUEST_DATA_STREAM when a vehicle refuses it, and asking again when a stream
 * falls silent. The rates fit the link the vehicles share ({@link TelemetryBudget}).
 * Runs on the communications thread.
 */
final class TelemetryRequests {


    private static final long MIN_SILENCE = 3_000_000_000L;
    /** A SiK radio's serial side at its default 57600 baud, 8N1. */
    private static final double SIK_SERIAL_BYTES_PER_SECOND = 5760;
    private static final Logger LOG = LoggerFactory.getLogger(TelemetryRequests.class);

    private static final class Stream {
        long intervalNanos;
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

    /** What a link's plan was made for: its vehicles and its bytes per second (NaN: unknown). */
    private record PlanInputs(int vehicles, double bytesPerSecond) {
    }

    private final MAVLinkCommunications comms;
    private final double hz;
    private final Map<MAVLinkNode, Vehicle> vehicles = new LinkedHashMap<>();
    private final Map<Link, PlanInputs> planned = new HashMap<>();
    private final Map<Link, TelemetryBudget.StreamRates> plans = new HashMap<>();
    private final Map<String, AtomicInteger> rerequests = new ConcurrentHashMap<>();

    TelemetryRequests(MAVLinkCommunications comms, double hz) {
        this.comms = comms;
        this.hz = hz;
    }

    void discovered(MAVLinkNode node, long now) {
        Vehicle v = new Vehicle();
        vehicles.put(node, v);
        Link link = node.getLink();
        int onLink = (int) vehicles.keySet().stream().filter(n -> n.getLink() == link).count();
        TelemetryBudget.StreamRates plan = replan(link, onLink, now, node);
        // asked for one at a time (a vehicle's commands of a kind queue up): what matters most first
        for (int i = TelemetryBudget.STREAMS.size() - 1; i >= 0; i--) {
            TelemetryBudget.AskedStream s = TelemetryBudget.STREAMS.get(i);
            v.streams.put(s.msgid(), new Stream(interval(plan, s.msgid()), s.optional()));
        }
        v.streams.forEach((id, s) -> request(node, v, id, s, now));
    }

    /**
     * Fits the streams of the link's vehicles to its bandwidth again when what it was fitted to
     * changed: a vehicle more, or a radio heard on a link whose bandwidth was not stated (a SiK
     * radio's host side runs at 57600 baud). The vehicles already asked, but {@code fresh}, are
     * asked again at their new rates.
     */
    private TelemetryBudget.StreamRates replan(Link link, int count, long now, MAVLinkNode fresh) {
        PlanInputs inputs = new PlanInputs(count, bytesPerSecond(link));
        TelemetryBudget.StreamRates plan = plans.get(link);
        if (inputs.equals(planned.get(link))) {
            return plan;
        }
        planned.put(link, inputs);
        plan = TelemetryBudget.plan(hz, inputs.vehicles(), inputs.bytesPerSecond());
        plans.put(link, plan);
        if (!plan.fits()) {
            LOG.warn("link {}: {} vehicles need {} bytes/s of telemetry at the slowest rates, more than half its {} bytes/s:"
                    + " their telemetry may lag", link, count, Math.round(plan.bytesPerSecond()), Math.round(inputs.bytesPerSecond()));
        } else if (plan.slowed()) {
            LOG.info("link {}: {} vehicles in {} bytes/s: telemetry slowed to {}", link, count,
                    Math.round(inputs.bytesPerSecond()), plan.slowedText(hz));
        }
        for (Map.Entry<MAVLinkNode, Vehicle> e : vehicles.entrySet()) {
            if (e.getKey().getLink() == link && e.getKey() != fresh) {
                for (Map.Entry<Integer, Stream> stream : e.getValue().streams.entrySet()) {
                    long interval = interval(plan, stream.getKey());
                    if (interval != stream.getValue().intervalNanos) {
                        stream.getValue().intervalNanos = interval;
                        request(e.getKey(), e.getValue(), stream.getKey(), stream.getValue(), now);
                    }
                }
            }
        }
        return plan;
    }

    private double bytesPerSecond(Link link) {
        if (link == null) {
            return Double.NaN;
        }
        OptionalDouble stated = link.url().bytesPerSecond();
        if (stated.isPresent()) {
            return stated.getAsDouble();
        }
        return comms.radioHeard(link) ? SIK_SERIAL_BYTES_PER_SECOND : Double.NaN;
    }

    private static long interval(TelemetryBudget.StreamRates plan, int msgid) {
        return Math.round(1e9 / plan.hz().get(msgid));
    }

    void seen(MAVLinkNode node, int msgid, long now) {
        Vehicle v = vehicles.get(node);
        Stream s = v == null ? null : v.streams.get(msgid);
        if (s != null) {
            s.lastSeen = now;
            s.seen = true;
        }
    }

    /**
     * Asks again for the streams that fell silent (vehicles that are lost are left alone), and fits
     * the streams to a link whose bandwidth became known.
     */
    void check(long now) {
        // one pass over the vehicles: a fleet of a thousand is checked four times a second
        Map<Link, Integer> onEachLink = new HashMap<>();
        vehicles.keySet().forEach(n -> onEachLink.merge(n.getLink(), 1, Integer::sum));
        onEachLink.forEach((link, count) -> replan(link, count, now, null));
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
                        requestDataStreams(node, v.streams.get(msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT).intervalNanos);
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
