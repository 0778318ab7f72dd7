package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code waitFor { c } then T} (reference A.2 "waitFor"). */
class WaitForSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "the task starts as soon as the guard holds: telemetry wakes the runtime between ticks"() {
        given:
        h.platform.node('1').battery = 0.5
        h.at(12.34) { h.platform.node('1').battery = 0.95 }

        when:
        def r = h.run('''
            v = pick { }
            execute v: waitFor { battery(v) >= 0.9 } then fly('m', 10)
        ''')

        then:
        r.outcome == COMPLETED
        h.platform.entries('start')*.time == [12.34d]
        def done = h.platform.entries('done')*.time
        done.size() == 1
        done[0] >= 22.34d && done[0] <= 22.44d + 1e-9      // 10 s later, on a 100 ms tick
    }

    def "the guard is evaluated on every step until it holds, then no more"() {
        when:
        h.run('''
            n = 0
            execute waitFor { ++n >= 5 } then idle(1)
        ''')

        then:
        h.engine.variable('n') == 5
        h.events.find { it.task.id == 'idle 1.0 s' && it.kind.name() == 'STARTED' }.time == 0.4d
        h.now() == 1.4d
    }

    def "the task starts in the tick where the guard becomes true"() {
        when:
        h.run('''
            v = pick { }
            t = (idle(2.5) >> action { post go: true }) | (waitFor { poll 'go' } then fly('m', 1))
            execute t
        ''')

        then:
        h.platform.journal*.toString() == ['start m 1 @2.5', 'done m 1 @3.5']
    }

    def "waitFor then builds a task without running it"() {
        when:
        def r = h.run('''
            v = pick { }
            n = 0
            t = waitFor { n++; true } then fly('m', 1)
        ''')

        then:
        r.outcome == COMPLETED
        h.engine.variable('n') == 0
        h.platform.journal.isEmpty()
    }

    def "a guard that throws aborts the script with the guard's line and stops what runs"() {
        given:
        h.platform.addNode('2')

        when:
        def r = h.run('''
            v = pick { count 2 }
            execute fly('other', 100) | (waitFor {
                throw new IllegalStateException('no telemetry')
            } then fly('m', 1))
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 4
        r.error.message.contains('IllegalStateException: no telemetry')
        h.platform.journal*.toString() == ['start other 1 @0.0', 'stop other 1 @0.0']
    }
}
