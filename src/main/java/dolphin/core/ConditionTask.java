package dolphin.core;

/** {@code condition { cond }}: DONE at the first step at which the condition holds. */
public final class ConditionTask extends LocalTask {

    private final Condition condition;

    public ConditionTask(Condition condition) {
        super("condition");
        this.condition = condition;
    }

    @Override
    public String kind() {
        return "condition";
    }

    @Override
    public TaskExecutor getExecutor() {
        return executor(ex -> condition.holds() ? CompletionState.DONE : CompletionState.IN_PROGRESS);
    }
}
