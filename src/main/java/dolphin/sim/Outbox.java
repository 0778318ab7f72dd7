package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_item_reached;
import com.MAVLink.common.msg_statustext;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * The order in which a simulated vehicle's link sends what one step of the vehicle (a tick, or the
 * handling of a message) had to say: messages asked for with MAV_CMD_REQUEST_MESSAGE first (after
 * the command's COMMAND_ACK, which goes out at once), then MISSION_ITEM_REACHED, one message with the last index
 * set (ArduPilot keeps one index and sends it deferred, so completions in one loop coalesce), then
 * the STATUSTEXTs in order, as ArduPilot's link sends its deferred messages before its text queue.
 * Other frames go out at once. Where ArduPilot spreads a step over two loops, the step flushes
 * between them.
 */
final class Outbox {

    private final Consumer<MAVLinkMessage> link;
    private final List<MAVLinkMessage> requested = new ArrayList<>();
    private final List<MAVLinkMessage> texts = new ArrayList<>();
    private int reached = -1;

    Outbox(Consumer<MAVLinkMessage> link) {
        this.link = link;
    }

    /** At once. */
    void send(MAVLinkMessage m) {
        link.accept(m);
    }

    /** With the next flush, as ArduPilot queues a requested message for its link's next send. */
    void requested(MAVLinkMessage m) {
        requested.add(m);
    }

    void text(int severity, String text) {
        msg_statustext t = new msg_statustext();
        t.severity = (short) severity;
        t.setText(text);
        texts.add(t);
    }

    void reached(int seq) {
        reached = seq;
    }

    /** Sends what waits: the requested messages, the MISSION_ITEM_REACHED, then the texts. */
    void flush() {
        for (MAVLinkMessage m : requested) {
            link.accept(m);
        }
        requested.clear();
        if (reached >= 0) {
            msg_mission_item_reached r = new msg_mission_item_reached();
            r.seq = reached;
            reached = -1;
            link.accept(r);
        }
        for (MAVLinkMessage t : texts) {
            link.accept(t);
        }
        texts.clear();
    }
}
