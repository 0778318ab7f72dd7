package dolphin.dsl

import dolphin.core.NodeSet
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED

/** {@code a + b}, {@code a - b}, {@code a & b}, {@code a | { n -> pred }} on vehicle sets (reference A.2 "Vehicle-set operators"). */
class VehicleSetOperatorsSpec extends Specification {

    ScriptHarness h = new ScriptHarness(3)

    private List<String> ids(String expression) {
        def r = h.run("""
            v1 = pick { }
            v2 = pick { }
            v3 = pick { }
            result = ${expression}
        """)
        assert r.outcome == COMPLETED
        def set = h.engine.variable('result')
        assert set instanceof NodeSet
        (set as NodeSet).ids()
    }

    def "#expression gives #expected"() {
        expect:
        ids(expression) == expected

        where:
        expression                          || expected
        'v3 + v1 + v2'                      || ['3', '1', '2']       // union, ordered a then b
        'v1 + v1'                           || ['1']
        '(v3 + v1 + v2) - v1'               || ['3', '2']            // difference
        'v1 - v1'                           || []
        '(v3 + v1 + v2) & (v2 + v1)'        || ['1', '2']            // intersection in a's order
        '(v1 + v2) & v3'                    || []
        "(v3 + v1 + v2) | { it.id != '1' }" || ['3', '2']            // subset by predicate
        "(v1 + v2) | { n -> false }"        || []
    }

    def "the subset predicate sees the node itself"() {
        given:
        h.platform.node('2').battery = 0.3

        expect:
        ids('(v1 + v2 + v3) | { n -> n.batteryRemaining() > 0.5 }') == ['1', '3']
    }

    def "operators make new sets and leave their operands alone"() {
        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            u = v1 + v2
            d = u - v1
        ''')

        then:
        (h.engine.variable('v1') as NodeSet).ids() == ['1']
        (h.engine.variable('u') as NodeSet).ids() == ['1', '2']
        (h.engine.variable('d') as NodeSet).ids() == ['2']
    }

    def "a computed set can restrict a task and key nothing else"() {
        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            v3 = pick { }
            execute fly('a', 1)[(v1 + v2 + v3) - v1 - v2]
        ''')

        then:
        h.platform.journal*.toString() == ['start a 3 @0.0', 'done a 3 @1.0']
    }

    def "the operators are methods of NodeSet: they work in plain Groovy code too"() {
        given:
        def a = h.platform.node('1')
        def b = h.platform.node('2')
        def c = h.platform.node('3')
        def ab = NodeSet.of(a, b)
        def bc = NodeSet.of(b, c)

        expect:
        (ab + bc).ids() == ['1', '2', '3']
        (ab - bc).ids() == ['1']
        (ab & bc).ids() == ['2']
        (ab | { it.id == '1' }).ids() == ['1']
    }
}
