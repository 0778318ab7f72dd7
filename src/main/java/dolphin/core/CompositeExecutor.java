package dolphin.core;

import java.util.List;

/** An executor that drives child executors; child i gets the sub-allocation {@code child(i)}. */
abstract class CompositeExecutor extends TaskExecutor {

    protected final List<TaskExecutor> children;

    CompositeExecutor(Task task, List<Task> childTasks) {
        super(task);
        this.children = childTasks.stream().map(Task::getExecutor).toList();
    }

    @Override
    List<TaskExecutor> children() {
        return children;
    }

    @Override
    protected void onInitialize(Allocation allocation) {
        for (int i = 0; i < children.size(); i++) {
            children.get(i).initialize(context(), allocation.child(i));
        }
    }

    /** Stops every child; one that fails to stop does not keep the others running. */
    @Override
    protected void onStop() {
        stopAll(children);
    }

    static void stopAll(List<TaskExecutor> executors) {
        RuntimeException first = null;
        for (TaskExecutor e : executors) {
            try {
                e.stop();
            } catch (RuntimeException ex) {
                if (first == null) {
                    first = ex;
                } else {
                    first.addSuppressed(ex);
                }
            }
        }
        if (first != null) {
            throw first;
        }
    }
}
