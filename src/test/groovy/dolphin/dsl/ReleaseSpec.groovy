package dolphin.dsl

import dolphin.core.NodeSet
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code release vset}: unbinds vehicles; nothing is sent to them (reference A.2 "release", B.3 releaseAll). */
class ReleaseSpec extends Specification {

    ScriptHarness h = new ScriptHarness(2)

    def "a released vehicle can be picked again"() {
        when:
        h.run('''
            a = pick { }
            release a
            b = pick { }
        ''')

        then:
        (h.engine.variable('b') as NodeSet).ids() == ['1']
    }

    def "without release the next pick gets another vehicle"() {
        when:
        h.run('''
            a = pick { }
            b = pick { }
        ''')

        then:
        (h.engine.variable('b') as NodeSet).ids() == ['2']
    }

    def "release calls nothing on the node"() {
        given:
        h.engine.bind('node1', h.platform.node('1'))

        when:
        def r = h.run('''
            a = pick { }
            release a
            callsRightAfter = node1.releases.size()
        ''')

        then:
        r.outcome == COMPLETED
        h.engine.variable('callsRightAfter') == 0
        h.platform.node('1').releases.isEmpty()     // not bound at the end, so not released then either
    }

    def "at the end of the script every vehicle still bound is released once"() {
        when:
        h.run('''
            a = pick { }
            b = pick { }
            release a
        ''')

        then:
        h.platform.node('1').releases.isEmpty()
        h.platform.node('2').releases == ['2']
    }

    def "a released vehicle is no longer available to execute"() {
        when:
        def r = h.run('''
            a = pick { }
            release a
            execute a: fly('x', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 4
        r.error.message.contains('no vehicles to run task')
        h.platform.journal.isEmpty()
    }

    def "release v1 + v2 releases both"() {
        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            release v1 + v2
            both = pick { count 2 }
        ''')

        then:
        (h.engine.variable('both') as NodeSet).ids() == ['1', '2']
    }

    def "releasing a vehicle that is not bound changes nothing"() {
        when:
        def r = h.run('''
            a = pick { }
            release a
            release a
            b = pick { count 2 }
        ''')

        then:
        r.outcome == COMPLETED
        (h.engine.variable('b') as NodeSet).ids() == ['1', '2']
    }
}
