package dolphin.mavlink;

import dolphin.mavlink.codec.Frame;
import java.nio.ByteBuffer;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The frames of one system heard in the last {@link #WINDOW}, each with the link that brought it
 * first: how a frame that a second link brings again is known (docs/mavlink.md, "One vehicle on two
 * links"). A frame is its component, sequence number, message id and payload; its signature is not
 * part of it. Not thread-safe: the communications thread's.
 */
final class RecentFrames {

    /** Longer than any difference in latency between two working links (LTE's worst is about a second). */
    static final long WINDOW = 2_000_000_000L;

    private record Identity(int compid, int seq, int msgid, ByteBuffer payload) {
    }

    private record Arrival(int link, long nanos) {
    }

    /** In the order heard, so the oldest are evicted from the front. */
    private final LinkedHashMap<Identity, Arrival> frames = new LinkedHashMap<>();

    /**
     * The index of the link that brought this frame first within the window; -1 if none did, and the
     * frame is then remembered as brought by {@code link}. A frame the same link brings again is
     * remembered anew: only another link's copy is a duplicate.
     */
    int firstLink(Frame frame, int link, long now) {
        evictBefore(now - WINDOW);
        Identity id = new Identity(frame.compid(), frame.seq(), frame.msgid(), ByteBuffer.wrap(frame.payload()));
        Arrival earlier = frames.get(id);
        if (earlier != null && earlier.link() != link) {
            return earlier.link();
        }
        frames.remove(id);
        frames.put(id, new Arrival(link, now));
        return -1;
    }

    /** Forgets the frames {@code link} brought first. */
    void forget(int link) {
        frames.values().removeIf(a -> a.link() == link);
    }

    private void evictBefore(long oldest) {
        Iterator<Map.Entry<Identity, Arrival>> it = frames.entrySet().iterator();
        while (it.hasNext() && it.next().getValue().nanos() < oldest) {
            it.remove();
        }
    }
}
