package dolphin.dsl

import dolphin.core.CompletionState
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.TASK_ERROR

/** {@code until { c } run T} and {@code T / { c }} (reference A.2 "T / { c } and until { c } run T"). */
class UntilSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    private List<String> journal() { h.platform.journal*.toString() }

    def "#form stops the task at the moment the condition holds and is DONE"() {
        given:
        h.at(25) { h.platform.node('1').battery = 0.2 }

        when:
        def r = h.run("""
            v = pick { }
            t = ${form}
            cs = execute t
        """)

        then:
        r.outcome == COMPLETED
        journal() == ['start m 1 @0.0', 'stop m 1 @25.0']
        h.engine.variable('cs') == CompletionState.DONE

        where:
        form << ["until { battery(v) < 0.3 } run fly('m', 100)",
                 "fly('m', 100) / { battery(v) < 0.3 }"]
    }

    def "telemetry between ticks cuts the task at once"() {
        given:
        h.at(25.05) { h.platform.node('1').battery = 0.2 }

        when:
        h.run('''
            v = pick { }
            execute fly('m', 100) / { battery(v) < 0.3 }
        ''')

        then:
        h.platform.entries('stop')*.time == [25.05d]
    }

    def "a task that ends first ends the constraint"() {
        when:
        def r = h.run("""
            v = pick { }
            execute ${form}
            execute fly('next', 1)
        """)

        then:
        r.outcome == COMPLETED
        journal() == ['start m 1 @0.0', 'done m 1 @10.0', 'start next 1 @10.0', 'done next 1 @11.0']

        where:
        form << ["until { false } run fly('m', 10)", "fly('m', 10) / { false }"]
    }

    def "a condition that already holds never starts the task"() {
        when:
        def r = h.run('''
            v = pick { }
            cs = execute fly('m', 10) / { true }
        ''')

        then:
        r.outcome == COMPLETED
        journal().isEmpty()
        h.engine.variable('cs') == CompletionState.DONE
    }

    def "the condition is checked before each step"() {
        when:
        h.run('''
            v = pick { }
            n = 0
            execute until { n++; false } run fly('m', 1)
        ''')

        then:
        h.engine.variable('n') == 11     // steps at 0.0, 0.1, ..., 1.0
    }

    def "an ERROR of the task passes through"() {
        when:
        def r = h.run('''
            v = pick { }
            cs = execute failing('f', 2, 'boom') / { false }
        ''')

        then:
        r.outcome == TASK_ERROR
        h.engine.variable('cs') == CompletionState.error('boom')
    }

    def "stopping a sequence inside a constraint stops the running child"() {
        given:
        h.at(15) { h.platform.node('1').battery = 0.2 }

        when:
        h.run('''
            v = pick { }
            t = (fly('a', 10) >> fly('b', 100)) / { battery(v) < 0.3 }
            execute t
        ''')

        then:
        journal() == ['start a 1 @0.0', 'done a 1 @10.0', 'start b 1 @10.0', 'stop b 1 @15.0']
    }
}
