package dolphin.core;

/**
 * A vehicle that is not there: what {@code pick} gives in a rehearsal, the run of a script without
 * vehicles that {@code dolphin check} makes to build its missions (docs/decisions.md, "Checking
 * scripts"). It has no telemetry; the words that need some end the rehearsal where they stand.
 */
public final class StandInNode implements Node {

    private final String id;
    private final String type;
    private double connectionTimeout = DEFAULT_CONNECTION_TIMEOUT;

    public StandInNode(String id, String type) {
        this.id = id;
        this.type = type;
    }

    @Override
    public String getId() {
        return id;
    }

    @Override
    public String getType() {
        return type;
    }

    @Override
    public Position getPosition() {
        return null;
    }

    @Override
    public Payload getPayload() {
        return Payload.NONE;
    }

    @Override
    public void release() {
    }

    @Override
    public double getConnectionTimeout() {
        return connectionTimeout;
    }

    @Override
    public void setConnectionTimeout(double seconds) {
        connectionTimeout = Node.validateConnectionTimeout(seconds);
    }

    @Override
    public boolean isConnected() {
        return true;
    }

    @Override
    public String toString() {
        return id;
    }
}
