package dolphin.core;

import java.util.List;

/**
 * {@code task / { cond }} and {@code until { cond } run task}: the condition is checked before each
 * step of the task; when it holds, the task is stopped and the constraint is DONE.
 *
 * <p>Unlike the original, the task is started at the first step whose check is false, so a
 * condition that already holds never starts it (no mission upload followed by an RTL).
 */
public final class ConstrainedTask extends WrapperTask {

    private final Condition until;

    public ConstrainedTask(Task inner, Condition until) {
        super(inner);
        this.until = until;
    }

    @Override
    public String getId() {
        return "(" + inner.getId() + " / {...})";
    }

    @Override
    public String kind() {
        return "until";
    }

    @Override
    public TaskExecutor getExecutor() {
        return new CompositeExecutor(this, List.of(inner)) {
            @Override
            protected CompletionState onStep() {
                return stepUnless(until.holds(), children.get(0));
            }
        };
    }

    /** Stops the child and finishes when {@code cut} is true, otherwise starts it if needed and steps it. */
    static CompletionState stepUnless(boolean cut, TaskExecutor child) {
        if (cut) {
            child.stop();
            return CompletionState.DONE;
        }
        if (child.getState() == TaskExecutor.State.READY) {
            child.start();
        }
        return child.step();
    }
}
