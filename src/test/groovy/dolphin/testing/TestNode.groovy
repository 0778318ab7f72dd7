package dolphin.testing

import dolphin.core.AbstractNode
import dolphin.core.Payload
import dolphin.core.Position

/** A vehicle whose state the test sets; each change wakes the runtime like telemetry would. */
class TestNode extends AbstractNode {
    private final TestPlatform platform
    private volatile double battery = 1.0d
    private volatile Position position
    private volatile boolean connected = true
    final List<String> releases = new java.util.concurrent.CopyOnWriteArrayList()

    TestNode(TestPlatform platform, String id, String type, Payload payload, Position position) {
        super(id, type, payload)
        this.platform = platform
        this.position = position
    }

    @Override
    double batteryRemaining() { battery }

    void setBattery(double value) {
        battery = value
        platform.telemetry()
    }

    @Override
    Position getPosition() { position }

    void setPosition(Position p) {
        position = p
        platform.telemetry()
    }

    @Override
    boolean isConnected() { connected }

    /** Simulates losing (false) or regaining (true) the link. */
    void setConnected(boolean value) {
        connected = value
        platform.telemetry()
    }

    @Override
    void release() { releases << id }
}
