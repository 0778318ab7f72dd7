package dolphin.core;

import java.util.List;

/** {@code when { cond } then task}: one branch of oneOf, allOf and waitFor. */
public record TaskGuard(Condition condition, Task task) {

    /**
     * Guarded sets allocate each branch from its own copy of the pool and then take away every
     * vehicle any branch uses, even branches that may never run.
     */
    static boolean allocateAll(List<TaskGuard> guards, NodeSet available, Allocation allocation) {
        NodeSet used = new NodeSet();
        boolean ok = true;
        for (int i = 0; i < guards.size() && ok; i++) {
            NodeSet pool = available.copy();
            ok = guards.get(i).task().allocate(pool, allocation.child(i));
            used = NodeSet.union(used, NodeSet.difference(available, pool));
        }
        available.removeAll(used);
        return ok;
    }

    static List<Task> tasks(List<TaskGuard> guards) {
        return guards.stream().map(TaskGuard::task).toList();
    }

    static String ids(List<TaskGuard> guards) {
        return String.join(", ", guards.stream().map(g -> g.task().getId()).toList());
    }
}
