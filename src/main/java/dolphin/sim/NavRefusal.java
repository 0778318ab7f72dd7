package dolphin.sim;

import java.util.List;

/**
 * A nav item a firmware does not start (ArduSub's Sub::start_command): the WARNING texts it says,
 * and whether its mission then stops there or goes on with the next item in the same update, as
 * AP_Mission does when a command fails to start.
 *
 * @param texts what it says, in order
 * @param stopsMission true: the mission stops at the item (NOT_STARTED); false: the item is skipped
 */
record NavRefusal(List<String> texts, boolean stopsMission) {

    NavRefusal {
        texts = List.copyOf(texts);
    }

    /** Refused with one text and skipped. */
    static NavRefusal skipped(String text) {
        return new NavRefusal(List.of(text), false);
    }
}
