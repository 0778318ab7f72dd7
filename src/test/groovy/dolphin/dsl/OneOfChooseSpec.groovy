package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR
import static dolphin.dsl.ScriptResult.Outcome.TASK_ERROR

/** {@code oneOf { ... }} and its synonym {@code choose { ... }} (reference A.2 "oneOf / choose"). */
class OneOfChooseSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "#word runs only the branch whose guard holds first"() {
        given:
        h.platform.node('1').battery = 0.6
        h.at(7) { h.platform.node('1').battery = 0.9 }
        h.at(9) { h.platform.node('1').battery = 0.1 }

        when:
        def r = h.run("""
            v = pick { }
            t = ${word} {
                when { battery(v) < 0.5 } then fly('low', 5)
                when { battery(v) > 0.8 } then fly('high', 5)
            }
            execute t
        """)

        then:
        r.outcome == COMPLETED
        h.platform.journal*.toString() == ['start high 1 @7.0', 'done high 1 @12.0']

        where:
        word << ['oneOf', 'choose']
    }

    def "#word prefers the earlier branch when several guards hold"() {
        when:
        h.run("""
            v = pick { }
            execute ${word} {
                when { true } then fly('a', 1)
                when { true } then fly('b', 1)
            }
        """)

        then:
        h.platform.entries('start')*.task == ['a']

        where:
        word << ['oneOf', 'choose']
    }

    def "#word passes the chosen branch's ERROR through"() {
        when:
        def r = h.run("""
            v = pick { }
            execute ${word} {
                when { false } then fly('a', 1)
                when { true } then failing('f', 1, 'boom')
            }
        """)

        then:
        r.outcome == TASK_ERROR
        h.platform.entries('error')*.task == ['f']

        where:
        word << ['oneOf', 'choose']
    }

    def "an empty #word is a script error naming what was expected"() {
        when:
        def r = h.run("""
            t = ${word} { }
        """)

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains("${word}: no choices were defined")
        r.error.message.contains("when { condition } then task")

        where:
        word << ['oneOf', 'choose']
    }

    def "'then' on the line after 'when' is a script error at the 'then' line"() {
        when:
        def r = h.run('''
            t = oneOf {
                when { true }
                then fly('a', 1)
            }
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 4
        r.error.message.contains("'then' begins a new statement")
    }
}
