package dolphin.core

import dolphin.testing.TestNode
import dolphin.testing.TestPlatform

/**
 * Drives one task tree by hand on a (non-advancing) ManualClock: allocate, initialise, start, then
 * step once per 100 ms tick. Also holds a small fleet of test vehicles, '1'..'n' by default.
 */
class Driver {
    final ManualClock clock = new ManualClock()
    final RecordingListener listener = new RecordingListener()
    final TaskContext context = new TaskContext(clock, listener)
    final TestPlatform platform = new TestPlatform()
    final Allocation allocation = new Allocation()
    TaskExecutor executor

    Driver(int vehicles = 3) {
        for (int i = 1; i <= vehicles; i++) {
            platform.addNode(String.valueOf(i))
        }
    }

    /** The fleet's vehicles, in platform order. */
    NodeSet all() { platform.connectedNodes }

    /** A set of the given vehicles, in the given order. */
    NodeSet set(String... ids) { new NodeSet(ids.collect { platform.node(it) }) }

    TestNode node(String id) { platform.node(id) }

    /** Allocates from {@code available} (all vehicles by default), initialises and starts the task. */
    TaskExecutor launch(Task task, NodeSet available = all()) {
        assert task.allocate(available.copy(), allocation): "allocation of ${task.id} failed: ${allocation.failure()}"
        executor = task.getExecutor()
        executor.initialize(context, allocation)
        executor.start()
        executor
    }

    /** One tick: a step, then 100 ms of clock time. */
    CompletionState tick() {
        CompletionState cs = executor.step()
        clock.advance(Environment.TICK)
        cs
    }

    /** Ticks {@code n} times and returns the states the steps returned. */
    List<CompletionState.Type> ticks(int n) {
        (1..n).collect { tick().type }
    }

    /** Steps once per tick until the executor completes (clock left at the last step). */
    CompletionState runToEnd(int maxTicks = 10_000) {
        for (int i = 0; i < maxTicks; i++) {
            CompletionState cs = executor.step()
            if (executor.isCompleted()) {
                return cs
            }
            clock.advance(Environment.TICK)
        }
        throw new AssertionError("${executor.task.id} did not complete within ${maxTicks} ticks")
    }

    double now() { clock.seconds() }

    /** The clock time as the journal prints it. */
    String time() { Journal.fmt(now()) }
}
