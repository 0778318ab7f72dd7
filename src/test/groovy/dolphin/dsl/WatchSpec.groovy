package dolphin.dsl

import dolphin.core.CompletionState
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.HALTED
import static dolphin.dsl.ScriptResult.Outcome.TASK_ERROR

/** {@code watch T onError { msg -> ... }} with ignore(), propagate() and halt (reference A.2 "watch", B.6). */
class WatchSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "ignore() turns the task's ERROR into DONE and says so"() {
        when:
        def r = h.run('''
            v = pick { }
            t = watch failing('f', 3, 'boom') onError { msg -> ignore() }
            cs = execute t
        ''')

        then:
        r.outcome == COMPLETED
        h.platform.journal*.toString() == ['start f 1 @0.0', 'error f 1 @3.0']
        h.messages.contains('watch: ignored the error of f: boom')
        (h.engine.variable('cs') as CompletionState).done
    }

    def "the handler gets the error message"() {
        when:
        h.run('''
            v = pick { }
            got = null
            execute watch(failing('f', 1, 'lost link')) onError { msg -> got = msg; ignore() }
        ''')

        then:
        h.engine.variable('got') == 'lost link'
    }

    def "#handler propagates the ERROR to the root"() {
        when:
        def r = h.run("""
            v = pick { }
            t = watch failing('f', 3, 'boom') onError ${handler}
            cs = execute t
        """)

        then:
        r.outcome == TASK_ERROR
        h.engine.variable('cs') == CompletionState.error('boom')
        h.messages.contains('task (watch f) ended in ERROR: boom')

        where:
        handler << ['{ msg -> propagate() }', '{ msg -> }', '{ ignore(); propagate() }']
    }

    def "an ignored error lets the sequence go on; a propagated one ends it"() {
        when:
        h.run("""
            v = pick { }
            t = (watch failing('f', 3, 'boom') onError { ${decision} }) >> fly('next', 1)
            execute t
        """)

        then:
        h.platform.entries('start')*.task == started

        where:
        decision     || started
        'ignore()'   || ['f', 'next']
        'propagate()'|| ['f']
    }

    def "the handler is not called when the task succeeds"() {
        when:
        def r = h.run('''
            v = pick { }
            called = false
            execute watch(fly('a', 1)) onError { called = true }
        ''')

        then:
        r.outcome == COMPLETED
        h.engine.variable('called') == false
    }

    def "halt inside the handler ends the program"() {
        when:
        def r = h.run('''
            v = pick { }
            execute watch(failing('f', 2, 'boom')) onError { msg -> halt "giving up: ${msg}" }
            message 'after'
        ''')

        then:
        r.outcome == HALTED
        r.message == 'giving up: boom'
        !h.messages.contains('after')
        h.platform.node('1').releases == ['1']
    }

    def "each error starts with propagate: the decision is not sticky"() {
        when:
        h.run('''
            v = pick { }
            n = 0
            w = watch failing('f', 1, 'boom') onError { msg -> n++; if (n == 1) ignore() }
            a = execute w
            b = execute w
            message "${a} / ${b}"
        ''')

        then:
        h.engine.variable('n') == 2
        h.messages.contains('DONE: boom / ERROR: boom')
    }

    def "watch passes DONE through"() {
        when:
        h.run('''
            v = pick { }
            cs = execute watch(fly('a', 2)) onError { ignore() }
        ''')

        then:
        h.engine.variable('cs') == CompletionState.DONE
        h.platform.journal*.toString() == ['start a 1 @0.0', 'done a 1 @2.0']
    }

    def "stopping the watcher stops the watched task"() {
        given:
        h.at(4) { h.platform.node('1').battery = 0.1 }

        when:
        h.run('''
            v = pick { }
            t = (watch fly('a', 100) onError { ignore() }) / { battery(v) < 0.2 }
            execute t
        ''')

        then:
        h.platform.journal*.toString() == ['start a 1 @0.0', 'stop a 1 @4.0']
    }
}
