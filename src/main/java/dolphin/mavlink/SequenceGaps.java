package dolphin.mavlink;

import java.util.HashMap;
import java.util.Map;

/**
 * Frames lost on a link, counted from the gaps in each sender's sequence numbers (system and
 * component), as MAVProxy's link statistics count them. A "gap" of half the sequence or more is a
 * duplicate or a frame that came after later ones, not a loss (the next one then counts a gap of one:
 * on links that reorder, the count is high). Not thread-safe:
 * its {@link LinkTraffic} holds the lock.
 */
final class SequenceGaps {

    private static final int LARGEST_LOSS = 127;

    private final Map<Integer, Integer> lastSeq = new HashMap<>();
    private long lost;

    void frame(int sysid, int compid, int seq) {
        Integer before = lastSeq.put(sysid << 8 | compid, seq);
        if (before != null) {
            int gap = (seq - before - 1) & 0xFF;
            if (gap <= LARGEST_LOSS) {
                lost += gap;
            }
        }
    }

    long lost() {
        return lost;
    }
}
