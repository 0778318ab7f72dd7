package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

class SmokeSpec extends Specification {

    def "a script picks a vehicle and runs a mission until a battery condition"() {
        given:
        def h = new ScriptHarness(2)
        h.at(30) { h.platform.node('1').battery = 0.2 }

        when:
        def result = h.run('''
            v1 = pick { type 'UAV'; timeout 5 }
            execute v1: (fly('survey', 100) / { battery(v1) < 0.3 }) >> fly('home', 10)
            message "done at ${10.minutes}"
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        h.platform.journal*.toString() == ['start survey 1 @0.0', 'stop survey 1 @30.0', 'start home 1 @30.0', 'done home 1 @40.0']
        h.messages.last() == 'done at 600.0'
    }
}
