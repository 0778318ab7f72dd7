package dolphin.web;

import dolphin.core.TaskEvent;
import dolphin.core.TaskTree;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The task trees of the script's executes and the state of every node, from the engine's events
 * (script thread), read by the sampler. A node is waiting until it starts, then running, then done,
 * error or stopped; nodes that never ran when their execute ends are skipped. The last
 * {@value #KEPT} executes are kept, so a script that loops does not grow without bound.
 */
final class TaskBoard {

    static final int KEPT = 20;

    private record NodeState(String state, double since, String message) {
    }

    private final double origin;
    private final ArrayDeque<TaskTree> executes = new ArrayDeque<>();
    private final Map<Long, NodeState> states = new HashMap<>();
    private final Map<Long, TaskTree> roots = new HashMap<>();
    private final Map<String, String> vehicleTasks = new HashMap<>();
    private long version;

    /** @param origin the run clock's seconds at which the run began: times are shown from there */
    TaskBoard(double origin) {
        this.origin = origin;
    }

    synchronized void executeStarted(TaskTree tree) {
        executes.addLast(tree);
        if (executes.size() > KEPT) {
            forget(executes.removeFirst());
        }
        roots.put(tree.occurrence(), tree);
        version++;
    }

    synchronized void taskEvent(TaskEvent event) {
        double time = event.time() - origin;
        NodeState state = switch (event.kind()) {
            case STARTED -> new NodeState("running", time, null);
            case STOPPED -> new NodeState("stopped", time, null);
            case COMPLETED -> new NodeState(event.state().isError() ? "error" : "done", time, event.state().getMessage());
        };
        states.put(event.occurrence(), state);
        if (event.isPlatformTask()) {
            String text = event.task().getId() + " " + state.state();
            event.vehicles().forEach(v -> vehicleTasks.put(v, text));
        }
        TaskTree root = roots.get(event.occurrence());
        if (root != null && event.kind() != TaskEvent.Kind.STARTED) {
            skipWaiting(root, time);
        }
        version++;
    }

    /** Changes with each event: the sampler sends the trees again only when it moved. */
    synchronized long version() {
        return version;
    }

    /** The last platform task on each vehicle and its state ("Survey Area 1 running"), by vehicle id. */
    synchronized Map<String, String> vehicleTasks() {
        return Map.copyOf(vehicleTasks);
    }

    /** The executes as JSON-ready maps, oldest first. */
    synchronized List<Object> json() {
        List<Object> list = new ArrayList<>();
        executes.forEach(t -> list.add(node(t)));
        return list;
    }

    private Map<String, Object> node(TaskTree t) {
        NodeState s = states.get(t.occurrence());
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("occurrence", t.occurrence());
        m.put("kind", t.kind());
        m.put("label", t.label());
        m.put("vehicles", t.vehicles());
        m.put("state", s == null ? "waiting" : s.state());
        m.put("since", s == null ? null : Json.tenths(s.since()));
        String detail = s == null ? null : s.message() != null ? s.message() : waitingDetail(t, s.state());
        if (detail != null) {
            m.put("detail", detail);
        }
        List<Object> children = new ArrayList<>();
        t.children().forEach(c -> children.add(node(c)));
        m.put("children", children);
        return m;
    }

    /** What a running node whose progress hangs on a condition is doing. */
    private String waitingDetail(TaskTree t, String state) {
        if (!"running".equals(state)) {
            return null;
        }
        boolean childRunning = t.children().stream().anyMatch(c -> {
            NodeState cs = states.get(c.occurrence());
            return cs != null && "running".equals(cs.state());
        });
        return switch (t.kind()) {
            case "condition" -> "waiting for its condition";
            case "waitFor", "oneOf", "allOf" -> childRunning ? null : "waiting for a condition";
            case "until" -> "until its condition holds";
            default -> null;
        };
    }

    private void skipWaiting(TaskTree t, double time) {
        states.putIfAbsent(t.occurrence(), new NodeState("skipped", time, null));
        t.children().forEach(c -> skipWaiting(c, time));
    }

    private void forget(TaskTree t) {
        states.remove(t.occurrence());
        roots.remove(t.occurrence());
        t.children().forEach(this::forget);
    }
}
