package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

import java.time.Duration
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit

/**
 * The units are a category active only on the script thread while a script runs: ordinary Groovy
 * code in the same JVM (this specification, other threads) never sees them.
 */
class UnitsLeakSpec extends Specification {

    static final List<String> UNITS = ['km', 'kilometers', 'meters', 'degrees', 'radians', 'north', 'east', 'south',
                                       'west', 'seconds', 'minutes', 'hours', 'days', 'percent']

    def "ordinary Groovy code has no unit '#unit'"() {
        when:
        5."${unit}"

        then:
        thrown(MissingPropertyException)

        where:
        unit << UNITS
    }

    def "the spec's own 10.minutes and 2.km fail, also after a script that used them has run"() {
        given:
        def h = new ScriptHarness(0)
        def r = h.run('x = 10.minutes + 2.km')

        when:
        def y = 10.minutes

        then:
        r.outcome == ScriptResult.Outcome.COMPLETED
        h.engine.variable('x') == 2600d
        thrown(MissingPropertyException)

        when:
        def z = 2.km

        then:
        thrown(MissingPropertyException)
    }

    def "no Number gains a unit property"() {
        given:
        new ScriptHarness(0).run('x = 1.km')

        expect:
        UNITS.every { 3.hasProperty(it) == null && 2.5d.hasProperty(it) == null }
    }

    def "while a script runs, its thread has units and the test thread has none"() {
        given:
        def h = new ScriptHarness(0)
        def asking = new CountDownLatch(1)
        def answer = new CountDownLatch(1)
        def onScriptThread = null
        h.engine.setInput { String prompt ->
            onScriptThread = 3.km        // this closure runs on the script thread
            asking.countDown()
            answer.await(10, TimeUnit.SECONDS)
            '1'
        }

        when:
        def run = h.engine.run("a = ask 'go?'\nb = 1.minutes", 'waiting.dolphin')
        assert asking.await(10, TimeUnit.SECONDS)
        Throwable onTestThread = null
        try {
            1.minutes
        } catch (MissingPropertyException e) {
            onTestThread = e
        }
        answer.countDown()
        def result = run.await(Duration.ofSeconds(10))

        then:
        onTestThread instanceof MissingPropertyException
        onScriptThread == 3000d
        result.outcome == ScriptResult.Outcome.COMPLETED
        h.engine.variable('b') == 60d
    }

    def "a thread the script starts does not get the units"() {
        given:
        def h = new ScriptHarness(0)

        when:
        h.run('''
            seen = null
            t = Thread.start {
                try {
                    seen = 2.km
                } catch (MissingPropertyException e) {
                    seen = 'no units'
                }
            }
            t.join()
            mine = 2.km
        ''')

        then:
        h.engine.variable('seen') == 'no units'
        h.engine.variable('mine') == 2000d
    }

    def "units are active in every run, not only the first"() {
        given:
        def h = new ScriptHarness(0)

        when:
        h.run('x = 1.km')
        h.run('y = 2.hours')

        then:
        h.engine.variable('y') == 7200d
    }

    def "operators need no metaclass change: ExpandoMetaClass is not enabled globally"() {
        given:
        new ScriptHarness(0).run('x = location(0, 0) ^ 1.km')

        expect:
        !(GroovySystem.metaClassRegistry.metaClassCreationHandler instanceof ExpandoMetaClassCreationHandle)
    }
}
