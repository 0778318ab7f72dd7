package dolphin.core;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Vehicles chosen for one occurrence of a task, as a tree that mirrors the task tree: a composite
 * hands child i the sub-allocation {@code child(i)}. Keying by position rather than by task object
 * lets one task object appear twice and run on two vehicles (the original sent both occurrences to
 * the vehicle allocated last).
 */
public final class Allocation {

    private final Map<Integer, Allocation> children = new LinkedHashMap<>();
    private List<Node> nodes = List.of();
    private String failure;

    public Allocation child(int index) {
        return children.computeIfAbsent(index, i -> new Allocation());
    }

    public List<Node> nodes() {
        return nodes;
    }

    public void assign(List<Node> chosen) {
        nodes = List.copyOf(chosen);
    }

    /** Every vehicle allocated anywhere in this subtree, in allocation order. */
    public Set<Node> allNodes() {
        Set<Node> all = new LinkedHashSet<>(nodes);
        children.values().forEach(c -> all.addAll(c.allNodes()));
        return Collections.unmodifiableSet(all);
    }

    /** Why allocation failed, from the first platform task that could not be served. */
    public String failure() {
        if (failure != null) {
            return failure;
        }
        for (Allocation c : new ArrayList<>(children.values())) {
            String f = c.failure();
            if (f != null) {
                return f;
            }
        }
        return null;
    }

    public void fail(String reason) {
        failure = reason;
    }
}
