package dolphin.core;

import java.util.List;

/** {@code a | b}: both run at once on distinct vehicles; DONE when both are, ERROR as soon as one fails. */
public final class ConcurrentTask implements Task {

    private final Task a;
    private final Task b;

    public ConcurrentTask(Task a, Task b) {
        this.a = a;
        this.b = b;
    }

    @Override
    public String getId() {
        return "(" + a.getId() + " | " + b.getId() + ")";
    }

    /** Both allocate from the same pool, so they get distinct vehicles. */
    @Override
    public boolean allocate(NodeSet available, Allocation allocation) {
        return a.allocate(available, allocation.child(0)) && b.allocate(available, allocation.child(1));
    }

    @Override
    public String kind() {
        return "concurrent";
    }

    @Override
    public TaskExecutor getExecutor() {
        return new CompositeExecutor(this, List.of(a, b)) {
            @Override
            protected void onStart() {
                children.forEach(TaskExecutor::start);
            }

            @Override
            protected CompletionState onStep() {
                boolean allDone = true;
                for (TaskExecutor child : children) {
                    CompletionState cs = child.isCompleted() ? child.getCompletionState() : child.step();
                    if (cs.isError()) {
                        stopAll(children);
                        return cs;
                    }
                    allDone &= cs.isDone();
                }
                return allDone ? CompletionState.DONE : CompletionState.IN_PROGRESS;
            }
        };
    }
}
