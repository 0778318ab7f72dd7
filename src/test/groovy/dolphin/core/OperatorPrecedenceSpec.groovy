package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout

/** Reference A.3 (operator precedence) and the vehicle-set operators of A.2, as Groovy sees them. */
@Timeout(30)
class OperatorPrecedenceSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()

    Probe fly(String id, double seconds) { Probe.lasting(journal, id, seconds) }

    def "a[v] >> b[v] | c[w] >> d[w] means (a[v] >> b[v]) | (c[w] >> d[w])"() {
        given:
        def v = d.set('1')
        def w = d.set('2')
        def a = fly('a', 0.2), b = fly('b', 0.1), c = fly('c', 0.1), e = fly('e', 0.3)
        Task t = a[v] >> b[v] | c[w] >> e[w]

        when:
        d.launch(t)
        d.runToEnd()

        then:
        t instanceof ConcurrentTask
        journal.lines() == ['start a 1 @0', 'start c 2 @0', 'done c 2 @0.1', 'start e 2 @0.1',
                            'done a 1 @0.2', 'start b 1 @0.2', 'done b 1 @0.3', 'done e 2 @0.4']
    }

    def "a >> b | c means (a >> b) | c: c runs beside the whole sequence"() {
        given:
        Task t = fly('a', 0.2) >> fly('b', 0.2) | fly('c', 0.1)

        when:
        d.launch(t)
        d.runToEnd()

        then:
        journal.lines('start') == ['start a 1 @0', 'start c 2 @0', 'start b 1 @0.2']
    }

    def "t / { c } | u means (t / { c }) | u: the condition cuts t only"() {
        given:
        Task t = fly('t', 9) / { d.now() >= 0.3 - 1e-9 } | fly('u', 0.5)

        when:
        d.launch(t)
        d.runToEnd()

        then: 'the constrained t starts lazily, at the first step, so after u (both at 0 s)'
        t instanceof ConcurrentTask
        journal.lines() == ['start u 2 @0', 'start t 1 @0', 'stop t 1 @0.3', 'done u 2 @0.5']
    }

    def "t[v] / { c } applies the constraint to the explicitly allocated task"() {
        given:
        Task t = fly('t', 9)[d.set('3')] / { d.now() >= 0.2 - 1e-9 }

        when:
        d.launch(t)
        d.runToEnd()

        then:
        t instanceof ConstrainedTask
        journal.lines() == ['start t 3 @0', 'stop t 3 @0.2']
    }

    def "vehicle-set operators: + union, - difference, & intersection, | subset by predicate"() {
        given:
        def a = d.set('1', '2')
        def b = d.set('3', '2')

        expect:
        (a + b).ids() == ['1', '2', '3']
        (b + a).ids() == ['3', '2', '1']
        (a - b).ids() == ['1']
        (a & b).ids() == ['2']
        (b & a).ids() == ['2']
        (d.all() | { Node n -> n.id != '2' }).ids() == ['1', '3']
        (a + b - a).ids() == ['3']
    }
}
