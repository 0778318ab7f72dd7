package dolphin.testing

import dolphin.core.NodeSet
import dolphin.core.Payload
import dolphin.core.Platform
import dolphin.core.Position
import dolphin.core.Task
import dolphin.core.VehicleEvent
import dolphin.dsl.DslExtension
import dolphin.dsl.ScriptContext
import groovy.transform.Immutable
import org.codehaus.groovy.control.customizers.ImportCustomizer

/**
 * A platform whose vehicles and tasks the test controls. It plugs into the engine through the
 * same interfaces as the MAVLink platform: Platform for vehicles, DslExtension for words.
 */
class TestPlatform implements Platform, DslExtension {

    @Immutable
    static class Entry {
        String kind
        String task
        String node
        double time

        String toString() { "${kind} ${task} ${node} @${time}" }
    }

    private final Map<String, TestNode> nodes = Collections.synchronizedMap(new LinkedHashMap<>())
    final List<Entry> journal = new java.util.concurrent.CopyOnWriteArrayList()
    final Map<String, Task> namedTasks = [:]
    final List<String> answers = []
    private volatile Runnable onTelemetry = {}
    private volatile java.util.function.Consumer<VehicleEvent> onVehicleEvent = {}

    TestNode addNode(String id, String type = 'UAV', Position position = Position.fromDegrees(41.185781, -8.70606486, 0),
                     List<String> payload = []) {
        def n = new TestNode(this, id, type, Payload.of(payload as String[]), position)
        nodes[id] = n
        n
    }

    TestNode node(String id) { nodes[id] }

    void telemetry() { onTelemetry.run() }

    /** Raises a vehicle event on the calling thread, as a platform does on whichever thread notices it. */
    void vehicleEvent(VehicleEvent event) { onVehicleEvent.accept(event) }

    void record(String kind, String task, String node, double time) {
        journal << new Entry(kind, task, node, time)
    }

    List<Entry> entries(String kind) { journal.findAll { it.kind == kind } }

    @Override
    String getName() { 'test' }

    @Override
    NodeSet getConnectedNodes() {
        synchronized (nodes) {
            new NodeSet(nodes.values().findAll { it.connected })
        }
    }

    @Override
    Task getPlatformTask(String id) {
        Task t = namedTasks[id]
        if (t == null) {
            throw new dolphin.core.EnvironmentException("the test platform has no task named '${id}'")
        }
        t
    }

    @Override
    void setTelemetryListener(Runnable r) { onTelemetry = r }

    @Override
    void setVehicleEventListener(java.util.function.Consumer<VehicleEvent> listener) { onVehicleEvent = listener }

    @Override
    String askForInput(String prompt) {
        answers ? answers.remove(0) : null
    }

    @Override
    void addImports(ImportCustomizer imports) {
        imports.addImports(Position.name)
    }

    @Override
    List<Object> words(ScriptContext context) { [new Words()] }

    /** The test platform's DSL words. */
    class Words {
        Task fly(String id, Number seconds) { new FlyTask(TestPlatform.this, id, seconds.doubleValue()) }

        Task failing(String id, Number after, String message) {
            new FlyTask(TestPlatform.this, id, Double.POSITIVE_INFINITY, after.doubleValue(), message)
        }
    }
}
