package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout

/** Reference A.2 "T[vset]" and A.4 (ResourceExplicit row). */
@Timeout(30)
class ResourceExplicitTaskSpec extends Specification {

    Driver d = new Driver(4)
    Journal journal = new Journal()

    def "t[v] builds a resource-explicit task whose executor is the task's own"() {
        given:
        def a = Probe.lasting(journal, 'a', 1)
        def t = a[d.set('2')]

        expect:
        t instanceof ResourceExplicitTask
        t.executor.task.is(a)
    }

    def "the task takes its vehicles only from the given set"() {
        given:
        def available = d.all()
        def allocation = new Allocation()

        expect:
        Probe.lasting(journal, 'a', 1)[d.set('3')].allocate(available, allocation)
        allocation.nodes()*.id == ['3']
        available.toString() == '{ 1 2 4 }'
    }

    def "a vehicle in the set but not available cannot be used"() {
        given:
        def available = d.set('1', '2')

        expect:
        !Probe.lasting(journal, 'a', 1)[d.set('3')].allocate(available, new Allocation())
    }

    def "afterwards the pool is (available - v) followed by what the task left of v"() {
        given:
        def available = d.all()

        when:
        def ok = Probe.lasting(journal, 'a', 1)[d.set('1', '2')].allocate(available, new Allocation())

        then:
        ok
        available.ids() == ['3', '4', '2']
    }

    def "a task running beside t[v] prefers vehicles outside v"() {
        given:
        def t = Probe.lasting(journal, 'a', 0.1)[d.set('1', '2')] | Probe.lasting(journal, 'b', 0.1)

        when:
        d.launch(t)
        d.runToEnd()

        then:
        journal.lines('start') == ['start a 1 @0', 'start b 3 @0']
    }

    def "two explicit tasks on disjoint sets run concurrently on their own vehicles"() {
        given:
        def t = Probe.lasting(journal, 'a', 0.2)[d.set('4')] | Probe.lasting(journal, 'b', 0.1)[d.set('2')]

        when:
        d.launch(t)
        def cs = d.runToEnd()

        then:
        cs.done
        journal.lines() == ['start a 4 @0', 'start b 2 @0', 'done b 2 @0.1', 'done a 4 @0.2']
    }

    def "explicit tasks on the same single vehicle cannot run concurrently, but can in sequence"() {
        given:
        def v = d.set('2')

        expect:
        !(Probe.lasting(journal, 'a', 1)[v] | Probe.lasting(journal, 'b', 1)[v]).allocate(d.all(), new Allocation())
        (Probe.lasting(journal, 'a', 1)[v] >> Probe.lasting(journal, 'b', 1)[v]).allocate(d.all(), new Allocation())
    }

    def "the set is taken when the task is built"() {
        given:
        def v = d.set('2')
        def t = Probe.lasting(journal, 'a', 1)[v]
        v.add(d.node('1'))
        def allocation = new Allocation()

        expect:
        t.allocate(d.all(), allocation)
        allocation.nodes()*.id == ['2']
    }
}
