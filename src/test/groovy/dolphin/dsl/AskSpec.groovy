package dolphin.dsl

import dolphin.core.Position
import dolphin.testing.ScriptHarness
import spock.lang.Specification

/** {@code ask 'prompt'}: reads a line and evaluates it as Groovy with the script's variables (reference A.2, E-22). */
class AskSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "ask reads through the platform more than once and evaluates each answer"() {
        given:
        h.platform.answers.addAll(['1 + 2', 'v * 10'])

        when:
        h.run('''
            v = 5
            a = ask 'first?'
            b = ask 'second?'
        ''')

        then:
        h.engine.variable('a') == 3
        h.engine.variable('b') == 50
        h.platform.answers.isEmpty()
    }

    def "an answer can use DSL words, units and the script's vehicle sets"() {
        given:
        h.platform.answers.addAll(['2.km', 'location(41, -8)', 'battery(v)'])

        when:
        h.run('''
            v = pick { }
            d = ask 'distance?'
            p = ask 'where?'
            b = ask 'battery?'
        ''')

        then:
        h.engine.variable('d') == 2000d
        h.engine.variable('p') == Position.fromDegrees(41, -8, 0)
        h.engine.variable('b') == 1.0d
    }

    def "Engine.setInput replaces the platform's input and sees each prompt"() {
        given:
        def prompts = []
        h.engine.setInput { String prompt -> prompts << prompt; "'answer ${prompts.size()}'".toString() }

        when:
        h.run('''
            a = ask 'name?'
            b = ask 'again?'
            message "${a}, ${b}"
        ''')

        then:
        prompts == ['name?', 'again?']
        h.messages == ['answer 1, answer 2']
    }

    def "an answer that does not compile is a script error at the ask line"() {
        given:
        h.platform.answers.add('1 +')

        when:
        def r = h.run('''
            a = 1
            b = ask 'number?'
        ''')

        then:
        r.outcome == ScriptResult.Outcome.SCRIPT_ERROR
        r.error.file == 'test.dolphin'
        r.error.line == 3
        r.error.message.contains("ask: the answer '1 +' is not valid")
    }

    def "an answer that fails at run time is a script error at the ask line"() {
        given:
        h.platform.answers.add('nosuch * 2')

        when:
        def r = h.run('''
            b = ask 'number?'
        ''')

        then:
        r.outcome == ScriptResult.Outcome.SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains("unknown name 'nosuch'")
    }

    def "no input gives null"() {
        when:
        h.run('''
            a = ask 'anything?'
            message "got ${a}"
        ''')

        then:
        h.messages == ['got null']
    }
}
