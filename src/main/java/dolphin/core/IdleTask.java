package dolphin.core;

/** {@code idle secs}: DONE at the first step at which the time has elapsed. */
public final class IdleTask extends LocalTask {

    private final double seconds;

    public IdleTask(double seconds) {
        super("idle " + seconds + " s");
        if (!(seconds >= 0)) {
            throw new EnvironmentException("idle: the duration must be a non-negative number of seconds, got " + seconds);
        }
        this.seconds = seconds;
    }

    @Override
    public String kind() {
        return "idle";
    }

    @Override
    public TaskExecutor getExecutor() {
        return executor(ex -> ex.timeElapsed() >= seconds ? CompletionState.DONE : CompletionState.IN_PROGRESS);
    }
}
