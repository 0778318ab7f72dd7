package dolphin.dsl

import dolphin.core.TaskEvent
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code idle secs} (reference A.2 "idle"). */
class IdleSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    private double completedAt(String id) {
        h.events.find { it.kind == TaskEvent.Kind.COMPLETED && it.task.id == id }.time
    }

    def "idle #secs needs no vehicle and ends on the first tick at or after #secs s: #end"() {
        when:
        def r = h.run("execute idle(${secs})")

        then:
        r.outcome == COMPLETED
        completedAt("idle ${secs as double} s") == end
        h.now() == end

        where:
        secs || end
        3    || 3.0d
        2.35 || 2.4d
        0.01 || 0.1d
        0    || 0.0d       // completes on its first step
    }

    def "idle in a sequence delays the next task"() {
        when:
        h.run('''
            v = pick { }
            t = idle 5
            execute t >> fly('a', 1)
        ''')

        then:
        h.platform.journal*.toString() == ['start a 1 @5.0', 'done a 1 @6.0']
    }

    def "idle takes units"() {
        when:
        h.run('execute idle(2.minutes)')

        then:
        h.now() == 120.0d
    }

    def "a negative idle is a script error"() {
        when:
        def r = h.run('''
            t = idle(-3)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains('non-negative')
    }
}
