package dolphin.core;

import java.util.List;

/** {@code during secs run task}: the task is stopped and this is DONE once the time has elapsed. */
public final class TimeConstrainedTask implements Task {

    private final Task inner;
    private final double seconds;

    public TimeConstrainedTask(Task inner, double seconds) {
        if (!(seconds >= 0)) {
            throw new EnvironmentException("during: the duration must be a non-negative number of seconds, got " + seconds);
        }
        this.inner = inner;
        this.seconds = seconds;
    }

    @Override
    public String getId() {
        return "(during " + seconds + " s run " + inner.getId() + ")";
    }

    @Override
    public boolean allocate(NodeSet available, Allocation allocation) {
        return inner.allocate(available, allocation.child(0));
    }

    @Override
    public TaskExecutor getExecutor() {
        return new CompositeExecutor(this, List.of(inner)) {
            @Override
            protected CompletionState onStep() {
                return ConstrainedTask.stepUnless(timeElapsed() >= seconds, children.get(0));
            }
        };
    }
}
