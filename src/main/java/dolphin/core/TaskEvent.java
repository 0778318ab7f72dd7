package dolphin.core;

import java.util.List;

/**
 * A change in a task's life: STARTED, COMPLETED (by itself, DONE or ERROR in {@code state}) or
 * STOPPED (cut short by its parent, a condition or the engine). {@code occurrence} names the executor, as
 * in the {@link TaskTree} of its execute.
 */
public record TaskEvent(Kind kind, Task task, List<String> vehicles, CompletionState state, double time, long occurrence) {

    public enum Kind { STARTED, COMPLETED, STOPPED }

    /** True for tasks that run on vehicles (platform tasks), as opposed to the operators' tasks. */
    public boolean isPlatformTask() {
        return task instanceof PlatformTask;
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "%.1fs %s %s%s%s", time, kind, task.getId(),
                vehicles.isEmpty() ? "" : " on " + String.join(",", vehicles),
                kind == Kind.COMPLETED ? " " + state : "");
    }
}
