package dolphin.mavlink;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.standard.msg_autopilot_version;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Asks each vehicle what it offers (AUTOPILOT_VERSION, whose capabilities say whether it has
 * MAVLink FTP) until it answers, and again when it comes back after being lost: one lost reply on a
 * radio must not send every later transfer item by item (docs/radios.md, "What the vehicle
 * offers"). The first ask goes at discovery; an unanswered one is repeated after
 * {@link #FIRST_WAIT} or three round-trip timeouts of the link, whichever is longer, the wait
 * doubling per unanswered ask up to {@link #LONGEST_WAIT}. The command itself is resent by the
 * {@link CommandSender} until acknowledged; this covers the reply lost after the acknowledgement.
 * Runs on the communications thread.
 */
final class CapabilityRequests {

    static final long FIRST_WAIT = 1_000_000_000L;
    static final long LONGEST_WAIT = 8_000_000_000L;

    private static final class Asking {
        long lastAsk;
        long wait;
    }

    /** Sends the request; the communications thread's, replaced by a recorder in specs. */
    interface Asker {
        void ask(MAVLinkNode node);
    }

    private final Asker asker;
    private final Map<MAVLinkNode, Asking> unanswered = new LinkedHashMap<>();

    CapabilityRequests(Asker asker) {
        this.asker = asker;
    }

    static CapabilityRequests of(MAVLinkCommunications comms) {
        return new CapabilityRequests(node -> comms.commandOnCommsThread(node, MAV_CMD.MAV_CMD_REQUEST_MESSAGE,
                msg_autopilot_version.MAVLINK_MSG_ID_AUTOPILOT_VERSION));
    }

    /** A vehicle just discovered, or heard again after it was lost: asked at once. */
    void ask(MAVLinkNode node, long now) {
        Asking a = new Asking();
        unanswered.put(node, a);
        send(node, a, now, FIRST_WAIT);
    }

    /** The vehicle's AUTOPILOT_VERSION came: no more asking until it is lost and heard again. */
    void answered(MAVLinkNode node) {
        unanswered.remove(node);
    }

    /**
     * A transfer wants the answer: asked again now unless an ask is already on its way (sent
     * less than a round-trip timeout ago). A vehicle that answered is not asked.
     */
    void hurry(MAVLinkNode node, long now) {
        Asking a = unanswered.get(node);
        if (a != null && now - a.lastAsk >= roundTripTimeout(node)) {
            send(node, a, now, a.wait);
        }
    }

    /** Asks again the connected vehicles whose wait has passed without an answer. */
    void check(long now) {
        unanswered.forEach((node, a) -> {
            if (node.isConnected() && now - a.lastAsk >= a.wait) {
                send(node, a, now, Math.min(LONGEST_WAIT, 2 * a.wait));
            }
        });
    }

    private void send(MAVLinkNode node, Asking a, long now, long nextWait) {
        a.lastAsk = now;
        a.wait = Math.max(nextWait, 3 * roundTripTimeout(node));
        node.capabilityAsked();
        asker.ask(node);
    }

    private static long roundTripTimeout(MAVLinkNode node) {
        return node.roundTrip().timeoutNanos(0);
    }
}
