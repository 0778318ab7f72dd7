package dolphin.mission.model;

import dolphin.core.Position;
import java.util.List;

/**
 * A command that becomes one or more mission items. Its position may be null for
 * commands that have none (speed, delay, camera).
 */
public abstract class MissionPoint extends DroneCommand {

    private final String word;
    private final Position position;

    /** @param word the DSL word that made the point, e.g. "moveAndLoiterTime" */
    protected MissionPoint(String word, Position position) {
        this.word = java.util.Objects.requireNonNull(word, "word");
        this.position = position;
    }

    @Override
    public final String name() {
        return word;
    }

    public Position getPosition() {
        return position;
    }

    /** The items, numbered from {@code seq}. */
    public abstract List<MissionItem> items(int seq);

    /** How many items {@link #items} emits; always equal to its size (the original's surveyArea declared fewer than it emitted). */
    public int messageCount() {
        return items(0).size();
    }

}
