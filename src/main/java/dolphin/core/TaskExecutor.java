package dolphin.core;

import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Runs one occurrence of a task: INITIALIZING, READY, EXECUTING, COMPLETED. Executors are driven
 * on the script thread, one {@link #step()} per tick, by their parent or by the Environment.
 *
 * <p>Each executor ends exactly once: either by itself ({@link #onCompletion()} after a DONE or
 * ERROR step) or cut short ({@link #onStop()}, only if it had started). A stop after the end is
 * ignored: the original ran the completion hook again at every stop.
 */
public abstract class TaskExecutor {

    public enum State { INITIALIZING, READY, EXECUTING, COMPLETED }

    private static final AtomicLong OCCURRENCES = new AtomicLong();

    private final Task task;
    private final long occurrence = OCCURRENCES.incrementAndGet();
    private volatile State state = State.INITIALIZING;
    private volatile CompletionState completionState = CompletionState.UNDEFINED;
    private volatile boolean stopped;
    private TaskContext context;
    private List<Node> vehicles = List.of();
    private long startNanos;

    protected TaskExecutor(Task task) {
        this.task = task;
    }

    public final Task getTask() {
        return task;
    }

    /** This occurrence's number, unique in the JVM: what task events and {@link TaskTree}s name it by. */
    public final long occurrence() {
        return occurrence;
    }

    /** The executors this one drives, made with it (so a task tree's shape is known when it starts). */
    List<TaskExecutor> children() {
        return List.of();
    }

    public final State getState() {
        return state;
    }

    public final CompletionState getCompletionState() {
        return completionState;
    }

    /** True when the executor ended because it was stopped, not by itself. */
    public final boolean wasStopped() {
        return stopped;
    }

    public final boolean isCompleted() {
        return state == State.COMPLETED;
    }

    protected final TaskContext context() {
        return context;
    }

    protected final Clock clock() {
        return context.clock();
    }

    public final void initialize(TaskContext ctx, Allocation allocation) {
        require(State.INITIALIZING);
        context = ctx;
        vehicles = List.copyOf(allocation.allNodes());
        onInitialize(allocation);
        state = State.READY;
    }

    public final void start() {
        require(State.READY);
        startNanos = clock().nanoTime();
        state = State.EXECUTING;
        emit(TaskEvent.Kind.STARTED);
        onStart();
    }

    public final CompletionState step() {
        require(State.EXECUTING);
        CompletionState cs = vehicleCheck();
        if (cs == null) {
            cs = onStep();
        }
        completionState = cs;
        if (cs.finished()) {
            state = State.COMPLETED;
            try {
                onCompletion();
            } finally {
                emit(TaskEvent.Kind.COMPLETED);
            }
        }
        return cs;
    }

    /**
     * Cuts the task short. A running executor gets {@link #onStop()}; one that never started is
     * only marked completed, so a mission that never flew sends nothing (the original sent it RTL).
     */
    public final void stop() {
        State before = state;
        if (before == State.COMPLETED) {
            return;
        }
        state = State.COMPLETED;
        stopped = true;
        completionState = CompletionState.UNDEFINED;
        if (before == State.EXECUTING) {
            try {
                onStop();
            } finally {
                emit(TaskEvent.Kind.STOPPED);
            }
        }
    }

    /** Clock seconds since {@link #start()}. */
    public final double timeElapsed() {
        return (clock().nanoTime() - startNanos) / 1e9;
    }

    /** The vehicles this occurrence runs on, its subtasks' included (empty for tasks that need none). */
    public List<Node> getVehicles() {
        return vehicles;
    }

    protected void onInitialize(Allocation allocation) {
    }

    protected void onStart() {
    }

    protected abstract CompletionState onStep();

    /** The task ended by itself, in DONE or ERROR. */
    protected void onCompletion() {
    }

    /** The task was cut short while running. */
    protected void onStop() {
    }

    /** A state that ends the step before {@link #onStep()}, or null; platform executors check their vehicles. */
    protected CompletionState vehicleCheck() {
        return null;
    }

    private void require(State expected) {
        if (state != expected) {
            throw new EnvironmentException("task " + task.getId() + ": expected " + expected
                    + " state, but it is " + state);
        }
    }

    private void emit(TaskEvent.Kind kind) {
        context.listener().taskEvent(new TaskEvent(kind, task,
                getVehicles().stream().map(Node::getId).toList(), completionState, clock().seconds(), occurrence));
    }
}
