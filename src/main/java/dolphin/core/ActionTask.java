package dolphin.core;

/** {@code action { code }}: runs the code once, at its first step. */
public final class ActionTask extends LocalTask {

    private final Runnable code;

    public ActionTask(Runnable code) {
        super("action");
        this.code = code;
    }

    @Override
    public String kind() {
        return "action";
    }

    @Override
    public TaskExecutor getExecutor() {
        return executor(ex -> {
            code.run();
            return CompletionState.DONE;
        });
    }
}
