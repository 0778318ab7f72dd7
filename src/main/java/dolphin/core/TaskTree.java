package dolphin.core;

import java.util.List;

/**
 * The shape of one execute's task tree as it starts, for viewers (the web view, an IDE): each node an
 * executor, named by its occurrence as the {@link TaskEvent}s that follow name it. Composites are
 * labelled by their kind ({@code sequence}, {@code until}...), leaves by their task's id (the
 * mission's name).
 *
 * @param vehicles the vehicles allocated to the node, its children's included
 */
public record TaskTree(long occurrence, String kind, String label, List<String> vehicles, List<TaskTree> children) {

    public TaskTree {
        vehicles = List.copyOf(vehicles);
        children = List.copyOf(children);
    }

    public static TaskTree of(TaskExecutor executor) {
        Task task = executor.getTask();
        List<TaskTree> children = executor.children().stream().map(TaskTree::of).toList();
        return new TaskTree(executor.occurrence(), task.kind(), children.isEmpty() ? task.getId() : task.kind(),
                executor.getVehicles().stream().map(Node::getId).toList(), children);
    }
}
