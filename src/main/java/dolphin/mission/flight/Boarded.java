package dolphin.mission.flight;

import dolphin.mission.model.MissionItem;
import java.util.List;

/**
 * A mission's items as the vehicle receives them, and the seqs of the items its family added (a
 * QuadPlane's landing approach): the ground-side commands keyed to later items move with them.
 */
record Boarded(List<MissionItem> items, List<Integer> added) {

    Boarded {
        items = List.copyOf(items);
        added = List.copyOf(added);
    }

    /** Where the mission's item {@code seq} went: one further on for each item added before it. */
    int seqOf(int seq) {
        int moved = seq;
        for (int a : added) {
            if (a <= moved) {
                moved++;
            }
        }
        return moved;
    }
}
