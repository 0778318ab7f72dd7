package dolphin.core;

/** {@code task[vehicles]}: the task may only take vehicles from the given set. */
public final class ResourceExplicitTask implements Task {

    private final Task inner;
    private final NodeSet vehicles;

    public ResourceExplicitTask(Task inner, NodeSet vehicles) {
        this.inner = inner;
        this.vehicles = vehicles.copy();
    }

    @Override
    public String getId() {
        return inner.getId() + vehicles;
    }

    /**
     * The task allocates from available ∩ vehicles; afterwards the pool is (available − vehicles)
     * followed by what the task left (as in the original), so a task allocated next prefers vehicles
     * outside this set.
     */
    @Override
    public boolean allocate(NodeSet available, Allocation allocation) {
        NodeSet pool = NodeSet.intersection(available, vehicles);
        NodeSet outside = NodeSet.difference(available, vehicles);
        boolean ok = inner.allocate(pool, allocation);
        if (ok) {
            available.clear();
            NodeSet.union(outside, pool).forEach(available::add);
        }
        return ok;
    }

    /** The inner task's own executor: {@code t[v]} adds no layer at run time. */
    @Override
    public TaskExecutor getExecutor() {
        return inner.getExecutor();
    }
}
