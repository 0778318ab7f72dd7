package dolphin.core;

import java.util.List;

/** {@code first >> second}: second starts, in the same tick, when first is DONE. */
public final class SequentialTask implements Task {

    private final Task first;
    private final Task second;

    public SequentialTask(Task first, Task second) {
        this.first = first;
        this.second = second;
    }

    @Override
    public String getId() {
        return "(" + first.getId() + " >> " + second.getId() + ")";
    }

    /** Each part allocates from its own copy, so both may use the same vehicle. */
    @Override
    public boolean allocate(NodeSet available, Allocation allocation) {
        NodeSet leftA = available.copy();
        NodeSet leftB = available.copy();
        boolean ok = first.allocate(leftA, allocation.child(0)) && second.allocate(leftB, allocation.child(1));
        NodeSet used = NodeSet.union(NodeSet.difference(available, leftA), NodeSet.difference(available, leftB));
        available.removeAll(used);
        return ok;
    }

    @Override
    public String kind() {
        return "sequence";
    }

    @Override
    public TaskExecutor getExecutor() {
        return new CompositeExecutor(this, List.of(first, second)) {
            @Override
            protected void onStart() {
                children.get(0).start();
            }

            @Override
            protected CompletionState onStep() {
                TaskExecutor a = children.get(0);
                TaskExecutor b = children.get(1);
                if (!a.isCompleted()) {
                    CompletionState cs = a.step();
                    if (cs.isError()) {
                        b.stop();
                        return cs;
                    }
                    if (!cs.isDone()) {
                        return cs;
                    }
                    b.start();
                }
                return b.step();
            }
        };
    }
}
