package dolphin.dsl

import dolphin.core.CompletionState
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR
import static dolphin.dsl.ScriptResult.Outcome.TASK_ERROR

/** {@code execute task} and {@code execute v1: t1, v2: t2, _: t3} (reference A.2 "execute", deviations E-3 and F-13). */
class ExecuteSpec extends Specification {

    ScriptHarness h = new ScriptHarness(3)

    private List<String> journal() { h.platform.journal*.toString() }

    def "execute runs a task on a picked vehicle, blocks until it ends and returns DONE"() {
        when:
        def r = h.run('''
            v = pick { }
            cs = execute fly('a', 5)
            execute fly('b', 3)
        ''')

        then:
        r.outcome == COMPLETED
        r.exitCode() == 0
        journal() == ['start a 1 @0.0', 'done a 1 @5.0', 'start b 1 @5.0', 'done b 1 @8.0']
        h.engine.variable('cs') == CompletionState.DONE
    }

    def "the first step comes right after the start and later steps every 100 ms"() {
        when:
        h.run('''
            v = pick { }
            execute fly('a', 0.25)
        ''')

        then:
        journal() == ['start a 1 @0.0', 'done a 1 @0.3']
    }

    def "execute v: task runs the task on the vehicle set held by the variable v"() {
        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            execute v2: fly('a', 1)
        ''')

        then:
        journal() == ['start a 2 @0.0', 'done a 2 @1.0']
    }

    def "the entries of an execute map run concurrently and execute returns when all have ended"() {
        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            execute v1: fly('a', 5),
                    v2: fly('b', 3)
            execute fly('c', 1)
        ''')

        then:
        journal() == ['start a 1 @0.0', 'start b 2 @0.0', 'done b 2 @3.0', 'done a 1 @5.0', 'start c 1 @5.0', 'done c 1 @6.0']
    }

    def "the key _ means no explicit vehicle set"() {
        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            execute v2: fly('a', 1), _: fly('b', 2)
        ''')

        then:
        journal() == ['start a 2 @0.0', 'start b 1 @0.0', 'done a 2 @1.0', 'done b 1 @2.0']
    }

    def "execute _: task is the same as execute task"() {
        when:
        h.run('''
            v = pick { }
            cs = execute _: fly('a', 1)
        ''')

        then:
        journal() == ['start a 1 @0.0', 'done a 1 @1.0']
        h.engine.variable('cs') == CompletionState.DONE
    }

    def "a task runs only on picked vehicles: with none picked it is a script error"() {
        when:
        def r = h.run('''
            execute fly('a', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains('no vehicles to run task a')
        journal().isEmpty()
    }

    def "a key whose set has too few vehicles for the task is a script error"() {
        when:
        def r = h.run('''
            v1 = pick { }
            v2 = pick { }
            execute v1: fly('a', 1) | fly('b', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 4
        r.error.message.contains('no vehicles to run task')
        journal().isEmpty()
    }

    def "a key that names no variable is a script error naming the key"() {
        when:
        def r = h.run('''
            v1 = pick { }
            execute vv: fly('a', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains("no script variable named 'vv'")
        r.error.message.contains("without 'def'")
    }

    def "a key declared with def is rejected before the script runs"() {
        when:
        def r = h.run('''
            def v = pick { }
            execute v: fly('a', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains("'v' is declared with 'def'")
        h.messages.every { !it.startsWith('picked') }     // nothing ran
    }

    def "a key whose variable holds no vehicle set is a script error"() {
        when:
        def r = h.run('''
            x = 5
            execute x: fly('a', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains("the key 'x' does not identify a vehicle set: it holds Integer")
    }

    def "an entry that is not a task is a script error"() {
        when:
        def r = h.run('''
            v = pick { }
            execute v: 'fly'
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains("the entry 'v:' is not a task but String")
    }

    def "executing null or a non-task is a script error, not an overloading puzzle"() {
        when:
        def r = h.run(source)

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains(expected)

        where:
        source                   || expected
        't = null\nexecute t'    || 'the task is null'
        'n = 5\nexecute n'       || 'expected a task'
    }

    def "a root ERROR is reported, the script goes on and the run ends as TASK_ERROR"() {
        when:
        def r = h.run('''
            v = pick { }
            cs = execute failing('f', 3, 'engine failure')
            message 'after'
            execute fly('b', 1)
        ''')

        then:
        r.outcome == TASK_ERROR
        r.exitCode() == 1
        r.message == '1 task(s) ended in ERROR'
        h.messages.indexOf('task f ended in ERROR: engine failure') < h.messages.indexOf('after')
        h.messages.contains('after')
        h.engine.variable('cs') == CompletionState.error('engine failure')
        journal() == ['start f 1 @0.0', 'error f 1 @3.0', 'start b 1 @3.0', 'done b 1 @4.0']
    }

    def "the script can act on the state execute returns"() {
        when:
        def r = h.run('''
            v = pick { }
            cs = execute failing('f', 1, 'no gps')
            if (cs.error) {
                message "retrying after: ${cs.message}"
                execute fly('again', 1)
            }
        ''')

        then:
        r.outcome == TASK_ERROR
        h.messages.contains('retrying after: no gps')
        h.platform.entries('done')*.task == ['again']
    }

    def "one task object in two execute entries runs on both vehicles (E-3)"() {
        when:
        h.run('''
            t = fly('shared', 10)
            v1 = pick { }
            v2 = pick { }
            execute v1: t, v2: t
        ''')

        then:
        journal().toSet() == ['start shared 1 @0.0', 'start shared 2 @0.0', 'done shared 1 @10.0', 'done shared 2 @10.0'].toSet()
    }

    def "one task object twice in a tree runs twice (#expression)"() {
        when:
        h.run("""
            t = fly('shared', 10)
            v1 = pick { }
            v2 = pick { }
            execute ${expression}
        """)

        then:
        h.platform.entries('start').collect { "${it.node}@${it.time}" } == starts

        where:
        expression      || starts
        't[v1] | t[v2]' || ['1@0.0', '2@0.0']
        't >> t'        || ['1@0.0', '1@10.0']
    }

    def "the two-word instructions can follow execute directly: #source"() {
        when:
        def r = h.run("""
            v1 = pick { }
            cs = ${source}
        """)

        then:
        r.outcome == COMPLETED
        journal() == expected
        (h.engine.variable('cs') as CompletionState).done

        where:
        source                                                        || expected
        "execute waitFor { true } then fly('a', 1)"                   || ['start a 1 @0.0', 'done a 1 @1.0']
        "execute v1: waitFor { true } then fly('a', 1)"               || ['start a 1 @0.0', 'done a 1 @1.0']
        "execute until { false } run fly('a', 1)"                     || ['start a 1 @0.0', 'done a 1 @1.0']
        "execute v1: until { false } run fly('a', 1)"                 || ['start a 1 @0.0', 'done a 1 @1.0']
        "execute during { 2 } run fly('a', 5)"                        || ['start a 1 @0.0', 'stop a 1 @2.0']
        "execute v1: during(2) run fly('a', 5)"                       || ['start a 1 @0.0', 'stop a 1 @2.0']
        "execute watch(failing('f', 1, 'x')) onError { ignore() }"    || ['start f 1 @0.0', 'error f 1 @1.0']
        "execute v1: watch(failing('f', 1, 'x')) onError { ignore() }"|| ['start f 1 @0.0', 'error f 1 @1.0']
    }

    def "entries after a two-word instruction still belong to the execute"() {
        when:
        def r = h.run('''
            v1 = pick { }
            v2 = pick { }
            execute v1: waitFor { true } then fly('a', 1), v2: until { false } run fly('b', 2), _: idle(3)
            execute fly('c', 1)
        ''')

        then:
        r.outcome == COMPLETED
        journal() == ['start a 1 @0.0', 'start b 2 @0.0', 'done a 1 @1.0', 'done b 2 @2.0', 'start c 1 @3.0', 'done c 1 @4.0']
    }

    def "an execute whose waitFor never gets its then is a script error at the execute line"() {
        when:
        def r = h.run('''
            v1 = pick { }
            execute v1: waitFor { true }
            message 'next'
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains("'v1: waitFor { ... }' has no 'then' part")
        journal().isEmpty()
    }

    def "a second half that does not fit the first is a script error"() {
        when:
        def r = h.run('''
            v1 = pick { }
            execute v1: waitFor { true } run fly('a', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains("'run' cannot follow waitFor or when: expected 'then'")
    }
}
