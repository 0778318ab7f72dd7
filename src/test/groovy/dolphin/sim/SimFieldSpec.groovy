package dolphin.sim

import dolphin.core.Position
import spock.lang.Specification


/** What the simulated sensors' fields are worth where a vehicle is. */
class SimFieldSpec extends Specification {

    static final Position CENTRE = Position.fromDegrees(40.4461, -7.3752, 820)

    def "a plume: its peak at the centre, half at half the radius, nothing at the radius and beyond"() {
        given:
        def plume = new PlumeField(CENTRE, 60, 100, 0)

        expect:
        Math.abs(plume.valueAt(CENTRE.displace(north, east, 0)) - value) < 1e-3

        where:
        north | east || value
        0     | 0    || 100
        30    | 0    || 50
        0     | -30  || 50
        -45   | 0    || 25
        60    | 0    || 0
        0     | 60.5 || 0
        500   | 500  || 0
    }

    def "a plume's background is added everywhere, and height does not matter"() {
        given:
        def plume = new PlumeField(CENTRE, 60, 100, 3)

        expect:
        Math.abs(plume.valueAt(CENTRE.displace(0, 30, -50)) - 53) < 1e-3
        plume.valueAt(CENTRE.displace(0, 1000, 0)) == 3
    }

    def "a linear field rises towards its bearing, falls away from it and is level across it"() {
        given: 'base 15 at the reference, 0.01 per metre towards the east'
        def field = new LinearField(CENTRE, 15, 0.01, 90)

        expect:
        Math.abs(field.valueAt(CENTRE.displace(north, east, 0)) - value) < 1e-4

        where:
        north | east || value
        0     | 0    || 15
        0     | 100  || 16
        0     | -100 || 14
        100   | 0    || 15
        -200  | 100  || 16
    }

    def "a bearing between the axes takes a share of each"() {
        given:
        def field = new LinearField(CENTRE, 0, 1, 45)

        expect:
        Math.abs(field.valueAt(CENTRE.displace(100, 0, 0)) - 100 / Math.sqrt(2)) < 1e-3
        Math.abs(field.valueAt(CENTRE.displace(100, -100, 0))) < 1e-3
    }

    def "a field's bad parameter is refused, naming it"() {
        when:
        make()

        then:
        def e = thrown(IllegalArgumentException)
        e.message == message

        where:
        make << [
                { -> new PlumeField(CENTRE, -5, 100, 0) },
                { -> new PlumeField(CENTRE, 0, 100, 0) },
                { -> new PlumeField(CENTRE, 60, Double.NaN, 0) },
                { -> new PlumeField(CENTRE, 60, 100, Double.POSITIVE_INFINITY) },
                { -> new PlumeField(Position.fromDegrees(91, 0, 0), 60, 100, 0) },
                { -> new LinearField(CENTRE, Double.NaN, 1, 0) },
                { -> new LinearField(CENTRE, 0, Double.NaN, 0) },
                { -> new LinearField(CENTRE, 0, 1, Double.NaN) }]
        message << [
                'the radius must be a positive number of metres, got -5.0',
                'the radius must be a positive number of metres, got 0.0',
                'the peak must be a finite number, got NaN',
                'the background must be a finite number, got Infinity',
                'the centre must have a latitude in [-90, 90] and a longitude in [-180, 180], got 91.0, 0.0',
                'the base value must be a finite number, got NaN',
                'the gradient must be a finite number, got NaN',
                'the bearing must be a finite number, got NaN']
    }

    def "a sensor's name fits NAMED_VALUE_FLOAT's ten characters"() {
        expect:
        new SimSensor('TEMPERATUR', new LinearField(CENTRE, 0, 0, 0)).name() == 'TEMPERATUR'

        when:
        new SimSensor(name, new LinearField(CENTRE, 0, 0, 0))

        then:
        def e = thrown(IllegalArgumentException)
        e.message.startsWith('a sensor name must be 1 to 10 printable ASCII characters')
        e.message.endsWith("got '${name}'")

        where:
        name << ['TEMPERATURE', '', 'CO 2', 'RAUCHGAS\u00dc']
    }

    def "vehicles by system id: all, none, or those listed"() {
        expect:
        SysidSet.ALL.contains(7)
        !SysidSet.NONE.contains(7)
        SysidSet.of([1, 3]).contains(3)
        !SysidSet.of([1, 3]).contains(2)
        SysidSet.of([1]).union(SysidSet.of([3])) == SysidSet.of([1, 3])
        SysidSet.of([1]).union(SysidSet.ALL) == SysidSet.ALL
        SysidSet.of([9, 1, 4]).outside(2, 5) == [1, 9] as Set

        when:
        SysidSet.of([0])

        then:
        def e = thrown(IllegalArgumentException)
        e.message == 'a system id must lie in 1..255, got 0'
    }
}
