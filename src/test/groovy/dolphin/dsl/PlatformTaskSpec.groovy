package dolphin.dsl

import dolphin.testing.FlyTask
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code task 'id'}: a task the platform knows by name (reference A.2 "task 'id'"). */
class PlatformTaskSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "task 'id' runs the platform's named task"() {
        given:
        h.platform.namedTasks['survey'] = new FlyTask(h.platform, 'survey', 10)
        h.platform.namedTasks['land'] = new FlyTask(h.platform, 'land', 2)

        when:
        def r = h.run('''
            v = pick { }
            execute task('survey') >> task('land')
            t = task 'survey'
            execute t
        ''')

        then:
        r.outcome == COMPLETED
        h.platform.journal*.toString() == ['start survey 1 @0.0', 'done survey 1 @10.0', 'start land 1 @10.0', 'done land 1 @12.0',
                                           'start survey 1 @12.0', 'done survey 1 @22.0']
    }

    def "an unknown task name is a script error with the platform's message"() {
        when:
        def r = h.run('''
            v = pick { }
            t = task 'nope'
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains("the test platform has no task named 'nope'")
    }
}
