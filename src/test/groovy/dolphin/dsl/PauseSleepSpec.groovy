package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED

/** {@code pause secs} and Groovy's {@code sleep(ms)}: both on the engine's clock (reference A.2 "pause"). */
class PauseSleepSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "#source waits #secs s of engine time before the next instruction"() {
        when:
        def r = h.run("""
            v = pick { }
            ${source}
            execute fly('a', 1)
        """)

        then:
        r.outcome == COMPLETED
        h.platform.entries('start')*.time == [secs]

        where:
        source            || secs
        'pause 2.5'       || 2.5d
        'pause 1.minutes' || 60d
        'pause 0'         || 0d
        'sleep 1500'      || 1.5d
        'sleep(250)'      || 0.25d
    }

    def "a one-hour pause takes virtual time, not real time"() {
        when:
        long start = System.nanoTime()
        h.run('pause 1.hours')
        double realSeconds = (System.nanoTime() - start) / 1e9

        then:
        h.now() == 3600d
        realSeconds < 10
    }

    def "pauses add up"() {
        when:
        h.run('''
            pause 1
            sleep 500
            pause 0.25
        ''')

        then:
        h.now() == 1.75d
    }
}
