package dolphin.core;

import java.util.List;

/** {@code watch task onError { msg -> ... }}: an ERROR of the task goes to the handler, which ignores (DONE) or propagates it. */
public final class WatcherTask extends WrapperTask {

    private final ErrorHandler handler;

    public WatcherTask(Task inner, ErrorHandler handler) {
        super(inner);
        this.handler = handler;
    }

    @Override
    public String getId() {
        return "(watch " + inner.getId() + ")";
    }

    @Override
    public String kind() {
        return "watch";
    }

    @Override
    public TaskExecutor getExecutor() {
        return new CompositeExecutor(this, List.of(inner)) {
            @Override
            protected void onStart() {
                children.get(0).start();
            }

            @Override
            protected CompletionState onStep() {
                CompletionState cs = children.get(0).step();
                if (!cs.isError()) {
                    return cs;
                }
                if (handler.handle(cs.getMessage()) == ErrorHandler.Decision.IGNORE) {
                    context().listener().message("watch: ignored the error of " + inner.getId() + ": " + cs.getMessage());
                    return CompletionState.done(cs.getMessage());
                }
                return cs;
            }
        };
    }
}
