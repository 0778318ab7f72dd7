package dolphin.dsl

import dolphin.core.Area
import dolphin.core.NodeSet
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED

/** Operator precedence of reference A.3: indexing > / > + - > >> > & > ^ > |. */
class PrecedenceSpec extends Specification {

    ScriptHarness h = new ScriptHarness(2)

    def "a[v] >> b[v] | c[w] >> d[w] runs as two concurrent sequences"() {
        when:
        def r = h.run('''
            v = pick { }
            w = pick { }
            execute fly('a', 10)[v] >> fly('b', 5)[v] | fly('c', 3)[w] >> fly('d', 4)[w]
        ''')

        then:
        r.outcome == COMPLETED
        h.platform.entries('start').collect { "${it.task} ${it.node} @${it.time}" } ==
                ['a 1 @0.0', 'c 2 @0.0', 'd 2 @3.0', 'b 1 @10.0']
        h.now() == 15.0d
    }

    def "m / {c} >> r means (m / {c}) >> r"() {
        given:
        h.at(20) { h.platform.node('1').battery = 0.2 }

        when:
        h.run('''
            v = pick { }
            execute fly('m', 100) / { battery(v) < 0.3 } >> fly('r', 10)
        ''')

        then:
        h.platform.journal*.toString() == ['start m 1 @0.0', 'stop m 1 @20.0', 'start r 1 @20.0', 'done r 1 @30.0']
    }

    def "a / {c} | b constrains only a"() {
        given:
        h.at(5) { h.platform.node('1').battery = 0.2 }

        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            execute fly('a', 100)[v1] / { battery(v1) < 0.3 } | fly('b', 20)[v2]
        ''')

        then:
        // a constraint starts its task at its first step, so b's start comes first within the tick
        h.platform.journal*.toString() == ['start b 2 @0.0', 'start a 1 @0.0', 'stop a 1 @5.0', 'done b 2 @20.0']
    }

    def "indexing binds tighter than >>: a >> b[w] restricts only b"() {
        when:
        h.run('''
            v = pick { }
            w = pick { }
            execute fly('a', 1) >> fly('b', 1)[w]
        ''')

        then:
        h.platform.entries('start').collect { "${it.task} ${it.node}" } == ['a 1', 'b 2']
    }

    def "+ and - bind tighter than &, and & tighter than |, for vehicle sets"() {
        given:
        h.platform.addNode('3')

        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            v3 = pick { }
            a = v1 + v2 & v2 + v3
            b = v1 + v2 + v3 - v2 & v3 + v1 | { it.id != '3' }
        ''')

        then:
        (h.engine.variable('a') as NodeSet).ids() == ['2']
        (h.engine.variable('b') as NodeSet).ids() == ['1']
    }

    def "location(...) ^ 2.km: command style needs parentheses around the location"() {
        when:
        h.run('''
            a = (location 38.43462, -8.86118) ^ 2.km
            b = location(38.43462, -8.86118) ^ 2.km
        ''')

        then:
        (h.engine.variable('a') as Area).radius == 2000d
        h.engine.variable('b') == h.engine.variable('a')
    }
}
