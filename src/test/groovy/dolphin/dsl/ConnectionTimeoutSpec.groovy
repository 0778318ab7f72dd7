package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code setConnectionTimeout secs} and {@code setConnectionTimeout v1: s1, ...} (reference A.2). */
class ConnectionTimeoutSpec extends Specification {

    ScriptHarness h = new ScriptHarness(3)

    private double timeout(String id) { h.platform.node(id).connectionTimeout }

    def "the scalar form sets the vehicles the script holds (Listing 1 picks, then gives its UUVs 10 minutes) and those picked later"() {
        when:
        def r = h.run('''
            a = pick { }
            setConnectionTimeout 10.minutes
            b = pick { }
            release b
            setConnectionTimeout 60
        ''')

        then:
        r.outcome == COMPLETED
        timeout('1') == 60d
        timeout('2') == 600d
        h.engine.environment.defaultConnectionTimeout == 60d
    }

    def "the map form sets the timeout of every vehicle in each named set"() {
        when:
        def r = h.run('''
            v1 = pick { count 2 }
            v2 = pick { }
            setConnectionTimeout v1: 30, v2: 1.hours
        ''')

        then:
        r.outcome == COMPLETED
        timeout('1') == 30d
        timeout('2') == 30d
        timeout('3') == 3600d
        h.engine.environment.defaultConnectionTimeout == 20d
    }

    def "#secs s is #verdict"() {
        when:
        def r = h.run("""
            v = pick { }
            setConnectionTimeout ${secs}
            setConnectionTimeout v: ${secs}
        """)

        then:
        (r.outcome == COMPLETED) == accepted
        accepted || r.error.line == 3
        accepted || r.error.message.contains("connection timeout must be between 5 and 3600 seconds, got ${secs as double}")

        where:
        secs   | accepted
        5      | true
        3600   | true
        4.9    | false
        3601   | false
        0      | false
        verdict = accepted ? 'accepted' : 'a script error'
    }

    def "a value out of range in the map form is a script error at its line"() {
        when:
        def r = h.run('''
            v = pick { }
            setConnectionTimeout v: 2
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains('connection timeout must be between 5 and 3600 seconds, got 2.0')
        timeout('1') == 20d
    }

    def "a map key that names no vehicle set is a script error"() {
        when:
        def r = h.run(source)

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 1
        r.error.message.contains(expected)

        where:
        source                              || expected
        'setConnectionTimeout vx: 30'       || "setConnectionTimeout: no script variable named 'vx'"
        'n = 3; setConnectionTimeout n: 30' || "setConnectionTimeout: the key 'n' does not identify a vehicle set"
    }
}
