package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR
import static dolphin.dsl.ScriptResult.Outcome.TASK_ERROR

/** {@code allOf { when {c} then T ... }}: every branch once, one at a time (reference A.2 "allOf", F-12). */
class AllOfSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    private List<String> journal() { h.platform.journal*.toString() }

    def "branches run one at a time in declaration order, on the same vehicle; the next starts on the next tick"() {
        when:
        def r = h.run('''
            v = pick { }
            t = allOf {
                when { true } then fly('a', 10)
                when { true } then fly('b', 5)
            }
            execute t >> fly('after', 1)
        ''')

        then:
        r.outcome == COMPLETED
        journal() == ['start a 1 @0.0', 'done a 1 @10.0', 'start b 1 @10.1', 'done b 1 @15.1',
                      'start after 1 @15.1', 'done after 1 @16.1']
    }

    def "when nothing runs, the first remaining branch whose guard holds starts"() {
        given:
        h.at(3) { h.platform.node('1').battery = 0.4 }

        when:
        h.run('''
            v = pick { }
            execute allOf {
                when { battery(v) < 0.5 } then fly('low', 5)
                when { true } then fly('any', 10)
            }
        ''')

        then:
        journal() == ['start any 1 @0.0', 'done any 1 @10.0', 'start low 1 @10.1', 'done low 1 @15.1']
    }

    def "allOf waits for a guard that does not hold yet"() {
        given:
        h.at(20) { h.platform.node('1').battery = 0.4 }

        when:
        h.run('''
            v = pick { }
            execute allOf {
                when { true } then fly('first', 5)
                when { battery(v) < 0.5 } then fly('low', 5)
            }
        ''')

        then:
        journal() == ['start first 1 @0.0', 'done first 1 @5.0', 'start low 1 @20.0', 'done low 1 @25.0']
    }

    def "an ERROR ends allOf at once and the other branches never run"() {
        when:
        def r = h.run('''
            v = pick { }
            execute allOf {
                when { true } then failing('f', 2, 'boom')
                when { true } then fly('b', 5)
            }
        ''')

        then:
        r.outcome == TASK_ERROR
        journal() == ['start f 1 @0.0', 'error f 1 @2.0']
        h.messages.any { it.endsWith('ended in ERROR: boom') }
    }

    def "guards that consume signals take them one branch at a time"() {
        when:
        h.run('''
            v = pick { }
            post job: 'a'
            post job: 'b'
            execute allOf {
                when { consume job: 'b' } then fly('b', 1)
                when { consume job: 'a' } then fly('a', 1)
            }
            left = poll 'job'
        ''')

        then:
        journal() == ['start b 1 @0.0', 'done b 1 @1.0', 'start a 1 @1.1', 'done a 1 @2.1']
        h.engine.variable('left') == false
    }

    def "an empty allOf is a script error naming what was expected"() {
        when:
        def r = h.run('''
            t = allOf {
            }
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains("allOf: no choices were defined; expected one or more 'when { condition } then task'")
    }
}
