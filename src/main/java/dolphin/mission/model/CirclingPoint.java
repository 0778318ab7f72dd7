package dolphin.mission.model;

import dolphin.core.Position;
import java.util.List;
import java.util.Objects;

/**
 * The loiters: one item at a centre with p1 (turns, seconds or 0), p3 = radius (metres, positive
 * clockwise) and p2 = p4 = 0, as the original builder writes them.
 */
abstract class CirclingPoint extends MissionPoint {

    private final int command;
    private final float param1;
    private final float radius;

    CirclingPoint(String word, Position center, int command, float param1, float radius) {
        super(word, Objects.requireNonNull(center, "center"));
        this.command = command;
        this.param1 = param1;
        this.radius = radius;
    }

    public float radius() {
        return radius;
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(MissionItem.at(seq, command, getPosition(), param1, 0, radius, 0));
    }
}
