package dolphin.dsl

import dolphin.core.Area
import dolphin.core.Position
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code location}, {@code area}, {@code ^}, {@code position} and {@code battery} (reference A.2). */
class GeoSpec extends Specification {

    ScriptHarness h = new ScriptHarness(0)

    private Object v(String name) { h.engine.variable(name) }

    def "location takes degrees (and metres) and stores radians"() {
        when:
        def r = h.run('''
            a = location(41.185781, -8.70606486)
            b = location(40.444233, -7.375234, 820)
            c = location 38.43462, -8.86118
        ''')

        then:
        r.outcome == COMPLETED
        v('a') == Position.fromDegrees(41.185781, -8.70606486, 0)
        (v('a') as Position).lat == Math.toRadians(41.185781)
        (v('b') as Position).hae == 820d
        v('c') == Position.fromDegrees(38.43462, -8.86118, 0)
    }

    def "location out of range is a script error: #source"() {
        when:
        def r = h.run("""
            ok = location(0, 0)
            bad = ${source}
        """)

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains(expected)

        where:
        source               || expected
        'location(91, 0)'    || 'latitude must be between -90 and 90 degrees, got 91'
        'location(-90.5, 0)' || 'latitude must be between -90 and 90 degrees, got -90.5'
        'location(0, 181)'   || 'longitude must be between -180 and 180 degrees, got 181'
    }

    def "the edges of the range are locations"() {
        expect:
        h.run('''
            a = location(90, 180)
            b = location(-90, -180)
        ''').outcome == COMPLETED
    }

    def "area(p, r) and p ^ r are the same area"() {
        when:
        h.run('''
            p = location(41.185781, -8.70606486)
            a = area(p, 500)
            b = p ^ 500
            c = (location 38.43462, -8.86118) ^ 2.km
            inside = a.contains(location(41.184742, -8.704601))        // 168.5 m away
            outside = area(p, 100).contains(location(41.184742, -8.704601))
        ''')

        then:
        v('a') == new Area(Position.fromDegrees(41.185781, -8.70606486, 0), 500)
        v('b') == v('a')
        (v('c') as Area).radius == 2000d
        (v('c') as Area).center == Position.fromDegrees(38.43462, -8.86118, 0)
        v('inside') == true
        v('outside') == false
    }

    def "position(v) is the vehicle's current position"() {
        given:
        def start = Position.fromDegrees(41, -8, 100)
        def later = Position.fromDegrees(41.001, -8, 120)
        h.platform.addNode('1', 'UAV', start)
        h.at(5) { h.platform.node('1').position = later }

        when:
        h.run('''
            v = pick { }
            before = position(v)
            pause 10
            after = position(v)
        ''')

        then:
        v('before') == start
        v('after') == later
    }

    def "position and battery want a set of exactly one vehicle: #source"() {
        given:
        h.platform.addNode('1')
        h.platform.addNode('2')

        when:
        def r = h.run("""
            v = pick { count 2 }
            x = ${source}
        """)

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains(expected)

        where:
        source               || expected
        'position(v)'        || 'position: the vehicle set must hold exactly one vehicle, but it holds 2: { 1 2 }'
        'battery(v)'         || 'battery: the vehicle set must hold exactly one vehicle, but it holds 2: { 1 2 }'
        'battery(v - v)'     || 'battery: the vehicle set must hold exactly one vehicle, but it holds 0'
    }

    def "position of a vehicle that has reported none is a script error"() {
        given:
        h.platform.addNode('1', 'UAV', null)

        when:
        def r = h.run('''
            v = pick { }
            p = position(v)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 3
        r.error.message.contains('vehicle 1 has not reported a position yet')
    }

    def "battery(v) is the remaining fraction and follows telemetry"() {
        given:
        h.platform.addNode('1').battery = 0.75
        h.at(3) { h.platform.node('1').battery = 0.3 }

        when:
        h.run('''
            v = pick { }
            before = battery(v)
            pause 5
            after = battery(v)
            low = battery(v) < 37.5.percent
        ''')

        then:
        v('before') == 0.75d
        v('after') == 0.3d
        v('low') == true
    }
}
