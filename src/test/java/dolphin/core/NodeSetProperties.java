package dolphin.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.function.Predicate;
import java.util.stream.Collectors;
import java.util.stream.IntStream;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/**
 * NodeSet algebra (reference B.4 and the vehicle-set operators of A.2): an insertion-ordered set
 * keyed by node id, with union (a then b), difference, intersection (in a's order) and subset.
 */
class NodeSetProperties {

    /** A bare node: only the id matters to a NodeSet; the tag tells instances with the same id apart. */
    static final class N implements Node {
        final String id;
        final String tag;

        N(String id, String tag) {
            this.id = id;
            this.tag = tag;
        }

        N(String id) {
            this(id, "first");
        }

        @Override
        public String getId() {
            return id;
        }

        @Override
        public String getType() {
            return "UAV";
        }

        @Override
        public Position getPosition() {
            return null;
        }

        @Override
        public Payload getPayload() {
            return Payload.NONE;
        }

        @Override
        public void release() {
        }

        @Override
        public double getConnectionTimeout() {
            return DEFAULT_CONNECTION_TIMEOUT;
        }

        @Override
        public void setConnectionTimeout(double seconds) {
        }

        @Override
        public boolean isConnected() {
            return true;
        }

        @Override
        public String toString() {
            return id + "/" + tag;
        }
    }

    /** Every id the generated sets draw from; small, so that sets overlap often. */
    static final List<String> UNIVERSE = IntStream.rangeClosed(1, 8).mapToObj(String::valueOf).toList();

    /** Lists of ids, with repeats, so that building a set from them also exercises first-wins add. */
    @Provide
    Arbitrary<List<String>> ids() {
        return Arbitraries.of(UNIVERSE).list().ofMinSize(0).ofMaxSize(10);
    }

    /** A set built by adding a fresh node per id, in list order. */
    static NodeSet set(List<String> ids) {
        NodeSet s = new NodeSet();
        ids.forEach(id -> s.add(new N(id)));
        return s;
    }

    /** The ids in first-occurrence order: what the set should hold. */
    static List<String> distinct(List<String> ids) {
        return new ArrayList<>(new LinkedHashSet<>(ids));
    }

    static List<String> idsOf(NodeSet s) {
        List<String> out = new ArrayList<>();
        s.forEach(n -> out.add(n.getId()));
        return out;
    }

    @Property
    void aSetHoldsEachIdOnceInFirstInsertionOrder(@ForAll("ids") List<String> ids) {
        NodeSet s = set(ids);
        assertEquals(distinct(ids), idsOf(s));
        assertEquals(distinct(ids), s.ids());
        assertEquals(distinct(ids).size(), s.size());
        assertEquals(ids.isEmpty(), s.isEmpty());
    }

    @Property
    void unionMembershipIsEitherAndCommutes(@ForAll("ids") List<String> a, @ForAll("ids") List<String> b) {
        NodeSet u = NodeSet.union(set(a), set(b));
        for (String id : UNIVERSE) {
            assertEquals(a.contains(id) || b.contains(id), u.contains(new N(id, "probe")), id);
        }
        assertEquals(u, NodeSet.union(set(b), set(a)));
    }

    @Property
    void unionIsOrderedAThenB(@ForAll("ids") List<String> a, @ForAll("ids") List<String> b) {
        List<String> expected = distinct(a);
        distinct(b).stream().filter(id -> !a.contains(id)).forEach(expected::add);
        assertEquals(expected, NodeSet.union(set(a), set(b)).ids());
    }

    @Property
    void differenceIsDisjointFromBAndOrderedAsA(@ForAll("ids") List<String> a, @ForAll("ids") List<String> b) {
        NodeSet d = NodeSet.difference(set(a), set(b));
        assertTrue(NodeSet.intersection(d, set(b)).isEmpty());
        d.forEach(n -> assertFalse(set(b).contains(n)));
        assertEquals(distinct(a).stream().filter(id -> !b.contains(id)).toList(), d.ids());
    }

    @Property
    void intersectionIsInBothAndOrderedAsA(@ForAll("ids") List<String> a, @ForAll("ids") List<String> b) {
        NodeSet i = NodeSet.intersection(set(a), set(b));
        i.forEach(n -> {
            assertTrue(set(a).contains(n));
            assertTrue(set(b).contains(n));
        });
        assertEquals(distinct(a).stream().filter(b::contains).toList(), i.ids());
        assertEquals(i, NodeSet.intersection(set(b), set(a)));
    }

    @Property
    void differencePlusIntersectionIsA(@ForAll("ids") List<String> a, @ForAll("ids") List<String> b) {
        NodeSet sa = set(a);
        NodeSet sb = set(b);
        NodeSet whole = NodeSet.union(NodeSet.difference(sa, sb), NodeSet.intersection(sa, sb));
        assertEquals(sa, whole);
        assertEquals(sa.size(), whole.size());
    }

    @Property
    void subsetKeepsTheMembersSatisfyingThePredicateInOrder(@ForAll("ids") List<String> a,
                                                            @ForAll("ids") List<String> chosen) {
        Predicate<Node> p = n -> chosen.contains(n.getId());
        NodeSet s = NodeSet.subset(set(a), p);
        assertEquals(distinct(a).stream().filter(chosen::contains).toList(), s.ids());
        assertEquals(s.ids(), set(a).or(p).ids());
    }

    @Property
    void operationsAreIdempotent(@ForAll("ids") List<String> a) {
        NodeSet s = set(a);
        assertEquals(s.ids(), NodeSet.union(s, s).ids());
        assertEquals(s.ids(), NodeSet.intersection(s, s).ids());
        assertTrue(NodeSet.difference(s, s).isEmpty());
        for (String id : distinct(a)) {
            assertFalse(s.add(new N(id, "again")));
        }
        assertEquals(distinct(a), s.ids());
    }

    @Property
    void theFirstNodeWithAnIdWins(@ForAll("ids") List<String> a) {
        NodeSet s = new NodeSet();
        List<N> firsts = new ArrayList<>();
        for (String id : a) {
            N first = new N(id, "first");
            N second = new N(id, "second");
            if (s.add(first)) {
                firsts.add(first);
            }
            assertFalse(s.add(second));
        }
        List<Node> members = new ArrayList<>();
        s.forEach(members::add);
        assertEquals(firsts.size(), members.size());
        for (int k = 0; k < firsts.size(); k++) {
            assertSame(firsts.get(k), members.get(k));
        }
    }

    @Property
    void unionKeepsTheNodesOfA(@ForAll("ids") List<String> a, @ForAll("ids") List<String> b) {
        NodeSet sa = new NodeSet();
        a.forEach(id -> sa.add(new N(id, "a")));
        NodeSet sb = new NodeSet();
        b.forEach(id -> sb.add(new N(id, "b")));
        NodeSet.union(sa, sb).forEach(n -> assertEquals(a.contains(n.getId()) ? "a" : "b", ((N) n).tag));
    }

    @Property
    void removeTakesTheIdOut(@ForAll("ids") List<String> a, @ForAll("ids") List<String> gone) {
        NodeSet s = set(a);
        for (String id : gone) {
            boolean had = s.contains(new N(id));
            int size = s.size();
            assertEquals(had, s.remove(new N(id, "other")));
            assertFalse(s.contains(new N(id)));
            assertEquals(had ? size - 1 : size, s.size());
        }
        assertEquals(distinct(a).stream().filter(id -> !gone.contains(id)).toList(), s.ids());
    }

    @Property
    void aCopyIsIndependent(@ForAll("ids") List<String> a) {
        NodeSet s = set(a);
        NodeSet c = s.copy();
        c.add(new N("99"));
        c.removeAll(set(a));
        assertEquals(distinct(a), s.ids());
        assertEquals(List.of("99"), c.ids());
    }

    @Property
    void theOperatorMethodsAreTheSetOperations(@ForAll("ids") List<String> a, @ForAll("ids") List<String> b) {
        NodeSet sa = set(a);
        NodeSet sb = set(b);
        assertEquals(NodeSet.union(sa, sb).ids(), sa.plus(sb).ids());
        assertEquals(NodeSet.difference(sa, sb).ids(), sa.minus(sb).ids());
        assertEquals(NodeSet.intersection(sa, sb).ids(), sa.and(sb).ids());
    }

    @Property
    void setOperationsDoNotChangeTheirArguments(@ForAll("ids") List<String> a, @ForAll("ids") List<String> b) {
        NodeSet sa = set(a);
        NodeSet sb = set(b);
        NodeSet.union(sa, sb);
        NodeSet.difference(sa, sb);
        NodeSet.intersection(sa, sb);
        NodeSet.subset(sa, n -> false);
        assertEquals(distinct(a), sa.ids());
        assertEquals(distinct(b), sb.ids());
    }

    @Property
    void toStringListsTheIdsInBraces(@ForAll("ids") List<String> a) {
        String expected = a.isEmpty() ? "{ }" : distinct(a).stream().collect(Collectors.joining(" ", "{ ", " }"));
        assertEquals(expected, set(a).toString());
    }

    @Example
    void toStringExamples() {
        assertEquals("{ 1 2 }", NodeSet.of(new N("1"), new N("2")).toString());
        assertEquals("{ 2 1 }", NodeSet.of(new N("2"), new N("1"), new N("2")).toString());
        assertEquals("{ }", new NodeSet().toString());
        assertEquals("{ 7 }", NodeSet.singleton(new N("7")).toString());
    }

    @Example
    void emptyIsSharedAndAddingToItThrows() {
        assertTrue(NodeSet.EMPTY.isEmpty());
        assertThrows(UnsupportedOperationException.class, () -> NodeSet.EMPTY.add(new N("1")));
        assertTrue(NodeSet.EMPTY.isEmpty());
        assertEquals("{ }", NodeSet.EMPTY.toString());
        assertTrue(NodeSet.EMPTY.copy().add(new N("1")));
        assertTrue(NodeSet.EMPTY.isEmpty());
    }

    @Example
    void equalityIsBySameIdsInAnyOrder() {
        assertEquals(NodeSet.of(new N("1"), new N("2")), NodeSet.of(new N("2", "x"), new N("1", "y")));
        assertFalse(NodeSet.of(new N("1")).equals(NodeSet.of(new N("1"), new N("2"))));
    }
}
