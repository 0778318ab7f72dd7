package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_item_reached;
import com.MAVLink.common.msg_statustext;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * The order in which a simulated vehicle's link sends what one step of the vehicle (a tick, or the
 * handling of a message) had to say: messages asked for with MAV_CMD_REQUEST_MESSAGE first (after
 * the command's COMMAND_ACK, which goes out at once), then MISSION_ITEM_REACHED, one message with the last index
 * set (ArduPilot keeps one index and sends it deferred, so completions in one loop coalesce), then
 * the STATUSTEXTs in order, as ArduPilot's link sends its deferred messages before its text queue.
 * Other frames go out at once. Where ArduPilot spreads a step over two loops, the step flushes
 * between them. An autopilot may send the last MISSION_ITEM_REACHED again, a second apart (PX4: ten
 * more times), and may send no text until a ground station was heard.
 */
final class Outbox {

    private static final long SECOND = 1_000_000_000L;

    private final Consumer<MAVLinkMessage> link;
    private final List<MAVLinkMessage> requested = new ArrayList<>();
    private final List<MAVLinkMessage> texts = new ArrayList<>();
    private final int reachedRepeats;
    private final BooleanSupplier textsHeard;
    private final LongSupplier clock;
    private int reached = -1;
    private int lastReached = -1;
    private int repeatsLeft;
    private long nextRepeat;

    /**
     * @param reachedRepeats how often the last MISSION_ITEM_REACHED goes out again, a second apart
     * @param textsHeard whether STATUSTEXT may go out now; those said meanwhile are dropped
     * @param clock the vehicle's clock time, nanoseconds
     */
    Outbox(Consumer<MAVLinkMessage> link, int reachedRepeats, BooleanSupplier textsHeard, LongSupplier clock) {
        this.link = link;
        this.reachedRepeats = reachedRepeats;
        this.textsHeard = textsHeard;
        this.clock = clock;
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
        if (!textsHeard.getAsBoolean()) {
            return;
        }
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
            lastReached = reached;
            repeatsLeft = reachedRepeats;
            nextRepeat = clock.getAsLong() + SECOND;
            reached = -1;
            link.accept(reachedMessage(lastReached));
        }
        for (MAVLinkMessage t : texts) {
            link.accept(t);
        }
        texts.clear();
    }

    /** The last MISSION_ITEM_REACHED again, when a repeat is due. */
    void tick(long now) {
        if (repeatsLeft > 0 && now >= nextRepeat) {
            repeatsLeft--;
            nextRepeat += SECOND;
            link.accept(reachedMessage(lastReached));
        }
    }

    private static msg_mission_item_reached reachedMessage(int seq) {
        msg_mission_item_reached r = new msg_mission_item_reached();
        r.seq = seq;
        return r;
    }
}
