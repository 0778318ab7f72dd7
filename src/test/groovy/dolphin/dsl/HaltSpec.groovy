package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.HALTED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code halt 'msg'} and {@code halt()} (reference A.2 "halt", B.6). */
class HaltSpec extends Specification {

    ScriptHarness h = new ScriptHarness(2)

    def "halt with a message ends the script as HALTED and releases the vehicles"() {
        when:
        def r = h.run('''
            v = pick { count 2 }
            halt 'low battery'
            message 'not reached'
        ''')

        then:
        r.outcome == HALTED
        r.exitCode() == 1
        r.message == 'low battery'
        r.error == null
        h.messages == ['picked { 1 2 } from the free vehicles { 1 2 }', 'halted: low battery']
        h.platform.node('1').releases == ['1']
        h.platform.node('2').releases == ['2']
    }

    def "halt() without a message"() {
        when:
        def r = h.run('''
            halt()
            message 'not reached'
        ''')

        then:
        r.outcome == HALTED
        r.message == 'halt'
        !h.messages.contains('not reached')
    }

    def "a bare halt is a script error that says how to write it"() {
        when:
        def r = h.run('''
            halt
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains("'halt' is a command")
        r.error.message.contains("'halt()'")
    }

    def "halt inside a running task stops the other tasks at that moment"() {
        when:
        def r = h.run('''
            v = pick { }
            execute fly('a', 100) | (idle(5) >> action { halt 'mid-flight' })
        ''')

        then:
        r.outcome == HALTED
        r.message == 'mid-flight'
        h.platform.journal*.toString() == ['start a 1 @0.0', 'stop a 1 @5.0']
        h.platform.node('1').releases == ['1']
    }
}
