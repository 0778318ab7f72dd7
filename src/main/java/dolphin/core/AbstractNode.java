package dolphin.core;

import java.util.concurrent.atomic.AtomicReference;

/**
 * Base class for platform nodes: identity, payload, connection timeout and battery. The payload is an
 * immutable value replaced whole when a node announces a component, so readers never see half of it.
 */
public abstract class AbstractNode implements Node {

    private final String id;
    private final String type;
    private final AtomicReference<Payload> payload;
    private volatile double connectionTimeout = DEFAULT_CONNECTION_TIMEOUT;

    protected AbstractNode(String id, String type, Payload payload) {
        this.id = id;
        this.type = type;
        this.payload = new AtomicReference<>(payload);
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
    public Payload getPayload() {
        return payload.get();
    }

    /** Adds a component the node turned out to carry (announced by it, or written in a fleet file). */
    public void addPayload(Payload.Component component) {
        payload.updateAndGet(p -> p.with(component));
    }

    @Override
    public double getConnectionTimeout() {
        return connectionTimeout;
    }

    @Override
    public void setConnectionTimeout(double seconds) {
        connectionTimeout = Node.validateConnectionTimeout(seconds);
    }

    /** The position for a script; a node whose telemetry may not have arrived yet waits a little for it. */
    public Position awaitPosition() {
        return getPosition();
    }

    /** Remaining battery as a fraction in [0, 1]; nodes without a battery report 1.0. */
    public double batteryRemaining() {
        return 1.0;
    }

    @Override
    public String toString() {
        return id;
    }
}
