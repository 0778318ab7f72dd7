package dolphin.dsl

import dolphin.core.TaskEvent
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code action { code }} and {@code condition { c }} (reference A.2). */
class ActionConditionSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "action runs its code once, at its first step, and needs no vehicle"() {
        when:
        def r = h.run('''
            n = 0
            t = action { n++; message "ran with n=${n}" }
            built = n
            execute idle(2) >> t
        ''')

        then:
        r.outcome == COMPLETED
        h.engine.variable('built') == 0
        h.engine.variable('n') == 1
        h.messages == ['ran with n=1']
        h.events.find { it.kind == TaskEvent.Kind.COMPLETED && it.task.id == 'action' }.time == 2.0d
    }

    def "the same action executed twice runs twice"() {
        when:
        h.run('''
            n = 0
            t = action { n++ }
            execute t
            execute t
        ''')

        then:
        h.engine.variable('n') == 2
    }

    def "an exception in an action aborts the script at the action's line"() {
        when:
        def r = h.run('''
            v = pick { }
            execute fly('a', 100) | (idle(3) >> action {
                throw new IllegalStateException('bad code')
            })
            message 'after'
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 4
        r.error.message.contains('IllegalStateException: bad code')
        !h.messages.contains('after')
        h.platform.journal*.toString() == ['start a 1 @0.0', 'stop a 1 @3.0']
    }

    def "condition is re-evaluated every step until it holds and needs no vehicle"() {
        when:
        def r = h.run('''
            n = 0
            execute condition { ++n >= 5 }
        ''')

        then:
        r.outcome == COMPLETED
        h.engine.variable('n') == 5
        h.now() == 0.4d
    }

    def "condition follows telemetry at once"() {
        given:
        h.at(7.77) { h.platform.node('1').battery = 0.4 }

        when:
        h.run('''
            v = pick { }
            execute condition { battery(v) < 0.5 } >> fly('r', 5)
        ''')

        then:
        h.platform.entries('start')*.time == [7.77d]
    }

    def "condition uses Groovy truth"() {
        when:
        h.run('''
            n = 0
            execute condition { n++ < 3 ? null : 'yes' }
        ''')

        then:
        h.engine.variable('n') == 4
    }
}
