package dolphin.core;

/**
 * A vehicle that is not there: what {@code pick} gives in a rehearsal, the run of a script without
 * vehicles that {@code dolphin check} makes to build its missions (docs/decisions.md, "Checking
 * scripts"). It has no telemetry; the words that need some end the rehearsal where they stand.
 */
public final class StandInNode extends AbstractNode {

    public StandInNode(String id, String type) {
        super(id, type, Payload.NONE);
    }

    @Override
    public Position getPosition() {
        return null;
    }

    @Override
    public void release() {
    }

    @Override
    public boolean isConnected() {
        return true;
    }
}
