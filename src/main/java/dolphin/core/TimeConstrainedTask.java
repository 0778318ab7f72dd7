package dolphin.core;

import java.util.List;

/** {@code during secs run task}: the task is stopped and this is DONE once the time has elapsed. */
public final class TimeConstrainedTask extends WrapperTask {

    private final double seconds;

    public TimeConstrainedTask(Task inner, double seconds) {
        super(inner);
        if (!(seconds >= 0)) {
            throw new EnvironmentException("during: the duration must be a non-negative number of seconds, got " + seconds);
        }
        this.seconds = seconds;
    }

    @Override
    public String getId() {
        return "(during " + seconds + " s run " + inner.getId() + ")";
    }

    @Override
    public String kind() {
        return "during";
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
