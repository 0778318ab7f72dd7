package dolphin.mavlink;

import com.MAVLink.common.msg_param_error;
import com.MAVLink.common.msg_param_request_read;
import com.MAVLink.common.msg_param_value;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.concurrent.CompletableFuture;

/**
 * Reads single parameters by name (PARAM_REQUEST_READ, answered by PARAM_VALUE), resending after
 * the command timeout. A parameter the vehicle says it lacks (PARAM_ERROR), or still unanswered
 * after the last attempt, is absent: older ArduPilot answers an unknown name with nothing. ArduPilot sends every value as a float cast of its type, so integers up to 2^24 come exact.
 * Reads of the same name on the same vehicle share one request. Runs on the communications thread only.
 */
final class ParameterReads {

    interface Request {
        void send(MAVLinkNode node, msg_param_request_read request);
    }

    private static final class Read {
        final MAVLinkNode node;
        final String name;
        final CompletableFuture<OptionalDouble> value = new CompletableFuture<>();
        int attempts;
        long deadline;

        Read(MAVLinkNode node, String name) {
            this.node = node;
            this.name = name;
        }
    }

    private final Request request;
    private final long timeoutNanos;
    private final int maxAttempts;
    private final Map<String, Read> pending = new LinkedHashMap<>();

    ParameterReads(Request request, long timeoutNanos, int maxAttempts) {
        this.request = request;
        this.timeoutNanos = timeoutNanos;
        this.maxAttempts = maxAttempts;
    }

    /** The parameter's value, or empty when the vehicle did not answer. */
    CompletableFuture<OptionalDouble> read(MAVLinkNode node, String name, long now) {
        Read p = pending.get(key(node, name));
        if (p == null) {
            p = new Read(node, name);
            pending.put(key(node, name), p);
            send(p, now);
        }
        return p.value;
    }

    void onValue(MAVLinkNode node, msg_param_value value) {
        answered(node, value.getParam_Id(), Float.isNaN(value.param_value) ? OptionalDouble.empty()
                : OptionalDouble.of(value.param_value));
    }

    /** Newer ArduPilot (since late 2025) answers an unknown name with PARAM_ERROR: absent at once, not after every attempt. */
    void onError(MAVLinkNode node, msg_param_error error) {
        answered(node, error.getParam_Id(), OptionalDouble.empty());
    }

    private void answered(MAVLinkNode node, String name, OptionalDouble value) {
        Read p = pending.remove(key(node, name));
        if (p != null) {
            p.value.complete(value);
        }
    }

    /** Resends what timed out, and gives up after the last attempt or once the vehicle is lost. */
    void tick(long now) {
        for (Iterator<Read> it = pending.values().iterator(); it.hasNext(); ) {
            Read p = it.next();
            if (now < p.deadline) {
                continue;
            }
            if (p.attempts >= maxAttempts || !p.node.isConnected()) {
                it.remove();
                p.value.complete(OptionalDouble.empty());
            } else {
                send(p, now);
            }
        }
    }

    private void send(Read p, long now) {
        msg_param_request_read m = new msg_param_request_read();
        m.target_system = (short) p.node.getMavLinkId();
        m.target_component = (short) p.node.getAutopilotCompid();
        m.setParam_Id(p.name);
        m.param_index = -1;
        p.attempts++;
        p.deadline = now + timeoutNanos;
        request.send(p.node, m);
    }

    private static String key(MAVLinkNode node, String name) {
        return node.getId() + "/" + name;
    }
}
