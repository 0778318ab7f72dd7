package dolphin.core;

import java.util.List;

/** A set of {@code when { cond } then task} branches (oneOf, waitFor, allOf). */
abstract class GuardedTask implements Task {

    protected final List<TaskGuard> guards;

    GuardedTask(String word, List<TaskGuard> guards) {
        if (guards.isEmpty()) {
            throw new EnvironmentException(word + ": no choices were defined (add when { condition } then task)");
        }
        this.guards = List.copyOf(guards);
    }

    @Override
    public boolean allocate(NodeSet available, Allocation allocation) {
        return TaskGuard.allocateAll(guards, available, allocation);
    }
}
