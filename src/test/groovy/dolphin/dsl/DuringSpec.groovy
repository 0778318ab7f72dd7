package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code during secs run T} and {@code during { secs } run T} (reference A.2 "during", F-11). */
class DuringSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "#form stops the task when the time is up"() {
        when:
        def r = h.run("""
            v = pick { }
            t = ${form}
            execute t
            execute fly('next', 1)
        """)

        then:
        r.outcome == COMPLETED
        h.platform.journal*.toString() == ['start m 1 @0.0', 'stop m 1 @10.0', 'start next 1 @10.0', 'done next 1 @11.0']

        where:
        form << ["during 10 run fly('m', 100)",
                 "during { 10 } run fly('m', 100)",
                 "during(10) run fly('m', 100)",
                 "during 10.seconds run fly('m', 100)",
                 "during { 5 + 5 } run fly('m', 100)"]
    }

    def "the closure is evaluated once, when the task is built"() {
        when:
        h.run('''
            v = pick { }
            d = 5
            t = during { d } run fly('m', 100)
            d = 50
            execute t
        ''')

        then:
        h.platform.entries('stop')*.time == [5.0d]
    }

    def "a duration of #secs s ends on the first 100 ms tick at or after it: #end s"() {
        when:
        h.run("""
            v = pick { }
            t = during ${secs} run fly('m', 100)
            execute t
        """)

        then:
        h.platform.entries('stop')*.time == [end]

        where:
        secs  || end
        0.05  || 0.1d
        2.35  || 2.4d
        0.1   || 0.1d
    }

    def "a duration of 0 ends at the first step, before the task starts"() {
        when:
        def r = h.run("""
            v = pick { }
            t = during 0 run fly('m', 100)
            execute t
        """)

        then:
        r.outcome == COMPLETED
        h.platform.journal.isEmpty()
        h.now() == 0.0d
    }

    def "a task that ends in time is not stopped"() {
        when:
        h.run('''
            v = pick { }
            t = during 10 run fly('m', 3)
            execute t
        ''')

        then:
        h.platform.journal*.toString() == ['start m 1 @0.0', 'done m 1 @3.0']
    }

    def "units work in both forms"() {
        when:
        h.run('''
            v = pick { }
            a = during 1.minutes run fly('a', 1000)
            b = during { 0.5.minutes } run fly('b', 1000)
            execute a >> b
        ''')

        then:
        h.platform.entries('stop')*.time == [60.0d, 90.0d]
    }

    def "a negative duration is a script error"() {
        when:
        def r = h.run('''
            v = pick { }
            t = during(-1) run fly('m', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains('non-negative')
    }
}
