package dolphin.core;

/** A task around one inner task (constraints, watch): it allocates what the inner task needs, as child 0. */
abstract class WrapperTask implements Task {

    protected final Task inner;

    WrapperTask(Task inner) {
        this.inner = inner;
    }

    @Override
    public boolean allocate(NodeSet available, Allocation allocation) {
        return inner.allocate(available, allocation.child(0));
    }
}
