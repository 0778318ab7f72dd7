package dolphin.core;

import java.util.ArrayList;
import java.util.List;

/**
 * {@code allOf { when {c} then t ... }}: every branch runs once, one at a time, each started when
 * no branch is running and its guard is the first (in declaration order) of the remaining ones to hold.
 */
public final class AllOfTask extends GuardedTask {

    public AllOfTask(List<TaskGuard> guards) {
        super("allOf", guards);
    }

    @Override
    public String getId() {
        return "(allOf " + TaskGuard.ids(guards) + ")";
    }

    @Override
    public String kind() {
        return "allOf";
    }

    @Override
    public TaskExecutor getExecutor() {
        return new CompositeExecutor(this, TaskGuard.tasks(guards)) {
            private final List<Integer> remaining = new ArrayList<>();
            private TaskExecutor running;

            @Override
            protected void onStart() {
                for (int i = 0; i < guards.size(); i++) {
                    remaining.add(i);
                }
            }

            @Override
            protected CompletionState onStep() {
                if (running == null) {
                    for (Integer i : remaining) {
                        if (guards.get(i).condition().holds()) {
                            remaining.remove(i);
                            running = children.get(i);
                            running.start();
                            break;
                        }
                    }
                    if (running == null) {
                        return CompletionState.IN_PROGRESS;
                    }
                }
                CompletionState cs = running.step();
                if (cs.isError()) {
                    stopAll(children);
                    return cs;
                }
                if (cs.isDone()) {
                    running = null;
                    return remaining.isEmpty() ? CompletionState.DONE : CompletionState.IN_PROGRESS;
                }
                return cs;
            }
        };
    }
}
