package dolphin.core;

import java.util.Collections;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * An insertion-ordered set of nodes, identified by node id. The operator methods give scripts
 * {@code a + b} (union), {@code a - b} (difference), {@code a & b} (intersection) and
 * {@code a | { n -> ... }} (subset).
 */
public final class NodeSet implements Iterable<Node> {

    /** The empty set; immutable. */
    public static final NodeSet EMPTY = new NodeSet(Collections.emptyMap());

    private final Map<String, Node> nodes;

    public NodeSet() {
        this.nodes = new LinkedHashMap<>();
    }

    public NodeSet(Iterable<? extends Node> initial) {
        this();
        initial.forEach(this::add);
    }

    private NodeSet(Map<String, Node> backing) {
        this.nodes = backing;
    }

    public static NodeSet of(Node... members) {
        return new NodeSet(List.of(members));
    }

    public static NodeSet singleton(Node n) {
        return of(n);
    }

    /** Adds a node unless one with the same id is already present (the first one wins). */
    public boolean add(Node n) {
        return nodes.putIfAbsent(n.getId(), n) == null;
    }

    public boolean contains(Node n) {
        return nodes.containsKey(n.getId());
    }

    public boolean remove(Node n) {
        return nodes.remove(n.getId()) != null;
    }

    public void removeAll(Iterable<? extends Node> others) {
        if (others == this) {
            clear();
            return;
        }
        others.forEach(this::remove);
    }

    public void clear() {
        nodes.clear();
    }

    public int size() {
        return nodes.size();
    }

    public boolean isEmpty() {
        return nodes.isEmpty();
    }

    public Stream<Node> stream() {
        return nodes.values().stream();
    }

    public List<String> ids() {
        return List.copyOf(nodes.keySet());
    }

    /** The single node of a one-node set. */
    public Node single(String what) {
        if (nodes.size() != 1) {
            throw new EnvironmentException(what + ": the vehicle set must hold exactly one vehicle, but it holds "
                    + nodes.size() + ": " + this);
        }
        return nodes.values().iterator().next();
    }

    public NodeSet copy() {
        return new NodeSet(nodes.values());
    }

    @Override
    public Iterator<Node> iterator() {
        return Collections.unmodifiableCollection(nodes.values()).iterator();
    }

    public static NodeSet union(NodeSet a, NodeSet b) {
        NodeSet r = a.copy();
        b.forEach(r::add);
        return r;
    }

    public static NodeSet difference(NodeSet a, NodeSet b) {
        NodeSet r = a.copy();
        r.removeAll(b);
        return r;
    }

    /** The members of a that are in b, in a's order. */
    public static NodeSet intersection(NodeSet a, NodeSet b) {
        return subset(a, b::contains);
    }

    public static NodeSet subset(NodeSet a, Predicate<? super Node> predicate) {
        return new NodeSet(a.stream().filter(predicate).toList());
    }

    public NodeSet plus(NodeSet other) {
        return union(this, other);
    }

    public NodeSet minus(NodeSet other) {
        return difference(this, other);
    }

    /** Anything but a vehicle set: a clear error, where Groovy would silently make {@code v + 3} a List. */
    public NodeSet plus(Object other) {
        throw notASet("+", other);
    }

    public NodeSet minus(Object other) {
        throw notASet("-", other);
    }

    private static IllegalArgumentException notASet(String operator, Object other) {
        return new IllegalArgumentException("a vehicle set " + operator + " " + (other == null ? "null"
                : "a " + other.getClass().getSimpleName() + " (" + other + ")")
                + ": vehicle sets combine only with vehicle sets, e.g. v1 " + operator + " v2");
    }

    public NodeSet and(NodeSet other) {
        return intersection(this, other);
    }

    public NodeSet or(Predicate<? super Node> predicate) {
        return subset(this, predicate);
    }

    /** Same ids, in any order. */
    @Override
    public boolean equals(Object o) {
        return o instanceof NodeSet s && s.nodes.keySet().equals(nodes.keySet());
    }

    @Override
    public int hashCode() {
        return nodes.keySet().hashCode();
    }

    /** The original's form: {@code { 1 2 }}. */
    @Override
    public String toString() {
        return nodes.isEmpty() ? "{ }" : nodes.keySet().stream().collect(Collectors.joining(" ", "{ ", " }"));
    }
}
