package dolphin.dsl.check;

import java.util.List;

/** What a finding says, and the names it suggests instead of the wrong one ("did you mean"), nearest first. */
record FindingText(String message, List<String> meant) {

    static FindingText of(String message) {
        return new FindingText(message, List.of());
    }
}
