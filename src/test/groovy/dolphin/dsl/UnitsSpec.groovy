package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

/** The units of reference A.2 "Units": metres, degrees and seconds are the base units. */
class UnitsSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    def "#expression == #expected"() {
        when:
        def r = h.run("x = ${expression}")

        then:
        r.outcome == ScriptResult.Outcome.COMPLETED
        Math.abs((h.engine.variable('x') as double) - expected) <= 1e-9 * Math.max(1, Math.abs(expected))

        where:
        expression        || expected
        '2.km'            || 2000
        '1.5.kilometers'  || 1500
        '750.meters'      || 750
        '45.degrees'      || 45
        'Math.PI.radians' || 180
        '1.radians'       || 180 / Math.PI
        '100.north'       || 100
        '100.east'        || 100
        '100.south'       || -100
        '100.west'        || -100
        '30.seconds'      || 30
        '10.minutes'      || 600
        '2.5.minutes'     || 150
        '2.hours'         || 7200
        '1.days'          || 86400
        '37.5.percent'    || 0.375
        '90.percent'      || 0.9
    }

    def "units combine with arithmetic and DSL words"() {
        given:
        h.platform.node('1').battery = 0.35

        when:
        h.run('''
            v = pick { }
            total = 1.hours + 30.minutes
            low = battery(v) < 37.5.percent
            pause 2.minutes
        ''')

        then:
        h.engine.variable('total') == 5400d
        h.engine.variable('low') == true
        h.now() == 120d
    }

    def "units work inside closures that the runtime evaluates later, on the script thread"() {
        given:
        h.at(40) { h.platform.node('1').battery = 0.25 }

        when:
        def r = h.run('''
            v = pick { }
            t = fly('m', 1000) / { battery(v) < 30.percent }
            execute t
        ''')

        then:
        r.outcome == ScriptResult.Outcome.COMPLETED
        h.platform.journal*.toString() == ['start m 1 @0.0', 'stop m 1 @40.0']
    }
}
