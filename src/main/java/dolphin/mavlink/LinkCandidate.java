package dolphin.mavlink;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.minimal.msg_heartbeat;
import dolphin.mavlink.codec.Frame;
import dolphin.mavlink.link.Link;
import java.lang.reflect.Field;
import java.net.SocketAddress;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntFunction;

/**
 * A system id heard on a link while a vehicle with that id is known on another (docs/mavlink.md,
 * "One vehicle on two links"). It is the same vehicle once {@link #SAME_AFTER} of its frames that
 * carry a time are byte for byte frames of that vehicle within {@link RecentFrames#WINDOW}; another
 * vehicle when {@link #DECIDE_WITHIN} passes without. The communications thread's.
 */
final class LinkCandidate {

    /**
     * Identical frames with a time that make it the same vehicle: two vehicles never send one such
     * frame (the sequence numbers alone agree once in 256, the times to the millisecond hardly ever),
     * let alone three.
     */
    static final int SAME_AFTER = 3;
    /** The fields that date a message: boot time in ms, or µs since boot or since 1970. */
    private static final List<String> TIME_FIELDS = List.of("time_boot_ms", "time_usec", "time_unix_usec");
    /**
     * GLOBAL_POSITION_INT, which we ask every vehicle for at 4 Hz, comes 16 times in it: room for
     * losses, and for a link a second or two behind the other.
     */
    static final long DECIDE_WITHIN = 4_000_000_000L;

    private final Link link;
    private final int sysid;
    private final IntFunction<MAVLinkNode> nodeOnLink;
    private final RecentFrames frames = new RecentFrames();
    private final Map<MAVLinkNode, Integer> matches = new HashMap<>();
    private final long started;
    private long lastNanos;
    private SocketAddress peer;
    private Frame heartbeat;

    /** {@code nodeOnLink} gives the vehicle with this system id on the link of that index, if any. */
    LinkCandidate(Link link, int sysid, IntFunction<MAVLinkNode> nodeOnLink, long now) {
        this.link = link;
        this.sysid = sysid;
        this.nodeOnLink = nodeOnLink;
        this.started = now;
        this.lastNanos = now;
    }

    Link link() {
        return link;
    }

    int sysid() {
        return sysid;
    }

    /** Where it was last heard from, on its link. */
    SocketAddress peer() {
        return peer;
    }

    /** Its last HEARTBEAT, for discovering it if it is another vehicle; null if none came. */
    Frame heartbeat() {
        return heartbeat;
    }

    /**
     * The frames the known vehicle processed, for it to take the link on: its later copies on this
     * link are duplicates. Those this link brought first were processed by none, so their copies on
     * the other link still are processed.
     */
    RecentFrames processedFrames() {
        frames.forget(link.index());
        return frames;
    }

    /** A frame on the candidate's link. */
    void heardHere(Frame frame, SocketAddress from, long now) {
        lastNanos = now;
        peer = from;
        if (frame.msgid() == msg_heartbeat.MAVLINK_MSG_ID_HEARTBEAT) {
            heartbeat = frame;
        }
        int first = frames.firstLink(frame, link.index(), now);
        MAVLinkNode known = first < 0 ? null : nodeOnLink.apply(first);
        if (known != null) {
            match(known, frame);
        }
    }

    /** A frame a known vehicle with the candidate's system id processed, on one of its links. */
    void heardKnown(MAVLinkNode node, Link on, Frame frame, long now) {
        if (frames.firstLink(frame, on.index(), now) == link.index()) {
            match(node, frame);
        }
    }

    /**
     * Only a frame with a time shows the same vehicle: two vehicles alike, in the same mode on the
     * ground, send the same HEARTBEAT and SYS_STATUS, and when they were started together (simulators
     * of one fleet) with the same sequence numbers too.
     */
    private void match(MAVLinkNode node, Frame frame) {
        if (carriesTime(frame.message())) {
            matches.merge(node, 1, Integer::sum);
        }
    }

    /** Whether the message has a time field that is set (a vehicle without a clock sends 0 in time_unix_usec). */
    static boolean carriesTime(MAVLinkMessage message) {
        if (message == null) {
            return false;
        }
        try {
            for (Field field : message.getClass().getFields()) {
                if (TIME_FIELDS.contains(field.getName()) && ((Number) field.get(message)).longValue() != 0) {
                    return true;
                }
            }
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("the generated message classes' fields are public", e);
        }
        return false;
    }

    /** The known vehicle it has shown itself to be, else null. */
    MAVLinkNode same() {
        return matches.entrySet().stream().filter(e -> e.getValue() >= SAME_AFTER).map(Map.Entry::getKey).findFirst().orElse(null);
    }

    /** Whether the time to show itself the same vehicle has passed: it is another. */
    boolean isOther(long now) {
        return now - started >= DECIDE_WITHIN;
    }

    /** Not heard for longer than it takes to decide: forgotten, so it starts afresh when heard again. */
    boolean isStale(long now) {
        return now - lastNanos > DECIDE_WITHIN;
    }
}
