package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

/** {@code message x}: a program message through the engine's listeners (reference A.2 "message"). */
class MessageSpec extends Specification {

    ScriptHarness h = new ScriptHarness(0)

    def "message #source shows #expected"() {
        when:
        h.run(source)

        then:
        h.messages == [expected]

        where:
        source                          || expected
        "message 'Done!'"               || 'Done!'
        'message 42'                    || '42'
        'message "v=${1 + 1}"'          || 'v=2'
        'message location(0, 0)'        || '(0.000000°, 0.000000°, 0.000)'
        'message null'                  || 'null'
        'message([1, 2])'               || '[1, 2]'
    }

    def "messages arrive in program order"() {
        when:
        h.run('''
            message 'one'
            execute idle(1)
            message 'two'
        ''')

        then:
        h.messages == ['one', 'two']
    }
}
