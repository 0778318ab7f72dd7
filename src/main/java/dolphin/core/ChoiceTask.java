package dolphin.core;

import java.util.List;

/**
 * {@code oneOf}/{@code choose} and {@code waitFor { c } then t}: the guards are scanned in order at
 * each step until one holds; that branch starts in the same step and its state is the result.
 */
public final class ChoiceTask extends GuardedTask {

    public ChoiceTask(List<TaskGuard> guards) {
        super("oneOf", guards);
    }

    @Override
    public String getId() {
        return guards.size() == 1 ? "(waitFor {...} then " + guards.get(0).task().getId() + ")"
                : "(oneOf " + TaskGuard.ids(guards) + ")";
    }

    @Override
    public String kind() {
        return guards.size() == 1 ? "waitFor" : "oneOf";
    }

    @Override
    public TaskExecutor getExecutor() {
        return new CompositeExecutor(this, TaskGuard.tasks(guards)) {
            private TaskExecutor chosen;

            @Override
            protected CompletionState onStep() {
                if (chosen == null) {
                    for (int i = 0; i < guards.size() && chosen == null; i++) {
                        if (guards.get(i).condition().holds()) {
                            chosen = children.get(i);
                        }
                    }
                    if (chosen == null) {
                        return CompletionState.IN_PROGRESS;
                    }
                    chosen.start();
                }
                return chosen.step();
            }
        };
    }
}
