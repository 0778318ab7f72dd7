package dolphin.core;

/** A task that runs on the ground station and needs no vehicle. */
abstract class LocalTask implements Task {

    private final String id;

    LocalTask(String id) {
        this.id = id;
    }

    @Override
    public String getId() {
        return id;
    }

    @Override
    public boolean allocate(NodeSet available, Allocation allocation) {
        return true;
    }

    /** An executor whose steps are given by {@code step}. */
    TaskExecutor executor(java.util.function.Function<TaskExecutor, CompletionState> step) {
        return new TaskExecutor(this) {
            @Override
            protected CompletionState onStep() {
                return step.apply(this);
            }
        };
    }
}
