package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

import static dolphin.core.CompletionState.Type.*

/** Reference A.2 "waitFor { c } then T" and "oneOf / choose", with the E-21 fix. */
@Timeout(30)
class ChoiceTaskSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()
    Map<String, Integer> checks = [:].withDefault { 0 }

    /** A guard named for counting, holding from the given clock time on. */
    TaskGuard when(String name, double from, Task task) {
        new TaskGuard({ -> checks[name]++; d.now() >= from - 1e-9 } as Condition, task)
    }

    def "waitFor: the guard is checked each step until true; then the task starts and is stepped in the same tick"() {
        given:
        d.launch(new ChoiceTask([when('g', 0.5, Probe.lasting(journal, 'a', 0.3))]))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        d.time() == '0.8'
        journal.lines() == ['start a 1 @0.5', 'done a 1 @0.8']
        journal.stepTimes('a') == ['0.5', '0.6', '0.7', '0.8']
        checks.g == 6
    }

    def "waitFor: a branch that is DONE at once ends the choice in the tick the guard became true"() {
        given:
        d.launch(new ChoiceTask([when('g', 0.3, new IdleTask(0))]))

        expect:
        d.ticks(4) == [IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, DONE]
    }

    @Unroll
    def "oneOf picks the first true guard in declaration order: guards from #from choose #chosen"() {
        given:
        def guards = ['a', 'b', 'c'].withIndex().collect { String id, int i ->
            when(id, from[i], Probe.lasting(journal, id, 0.2))
        }
        d.launch(new ChoiceTask(guards))

        when:
        d.runToEnd()

        then:
        journal.lines('start', 'done')*.split(' ')*.getAt(1).unique() == [chosen]

        where:
        from            || chosen
        [0, 0, 0]       || 'a'
        [9, 0, 0]       || 'b'
        [9, 9, 0]       || 'c'
        [0.5, 0.3, 0.3] || 'b'
        [0.3, 0.5, 0.1] || 'c'
        [0.3, 0.5, 0.3] || 'a'
    }

    def "once chosen, only the chosen branch is stepped, the guards are not checked again and its state is the result"() {
        given:
        d.launch(new ChoiceTask([when('a', 9, Probe.lasting(journal, 'a', 1)),
                                 when('b', 0.2, Probe.lasting(journal, 'b', 0.3)),
                                 when('c', 0.2, Probe.lasting(journal, 'c', 1))]))

        when:
        def states = d.ticks(6)

        then:
        states == [IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, DONE]
        journal.lines() == ['start b 1 @0.2', 'done b 1 @0.5']
        journal.stepTimes('a').empty
        journal.stepTimes('c').empty
        checks == [a: 3, b: 3, c: 2]
    }

    def "an ERROR of the chosen branch is passed through"() {
        given:
        d.launch(new ChoiceTask([when('a', 0, Probe.failing(journal, 'a', 0.1, 'refused'))]))

        expect:
        d.runToEnd() == CompletionState.error('refused')
    }

    def "stopped before anything was chosen, the choice evaluates no guard and starts or stops nothing (E-21)"() {
        given:
        d.launch(new ChoiceTask([when('a', 9, Probe.lasting(journal, 'a', 1)), when('b', 9, Probe.lasting(journal, 'b', 1))]))
        d.ticks(3)
        def before = new HashMap(checks)

        when:
        d.executor.stop()

        then:
        checks == before
        checks == [a: 3, b: 3]
        journal.lines().empty
    }

    def "stopped after a branch was chosen, the choice stops that branch only"() {
        given:
        d.launch(new ChoiceTask([when('a', 9, Probe.lasting(journal, 'a', 1)), when('b', 0.1, Probe.lasting(journal, 'b', 1))]))
        d.ticks(4)

        when:
        d.executor.stop()

        then:
        journal.lines() == ['start b 1 @0.1', 'stop b 1 @0.4']
    }

    def "a choice without guards is rejected"() {
        when:
        new ChoiceTask([])

        then:
        def e = thrown(EnvironmentException)
        e.message.contains('no choices')
    }

    def "each branch allocates from its own copy; every vehicle any branch uses is taken (A.4)"() {
        given:
        def available = d.all()
        def allocation = new Allocation()
        def t = new ChoiceTask([when('a', 0, Probe.lasting(journal, 'a', 1)),
                                when('b', 0, Probe.lasting(journal, 'b', 1, 2))])

        expect:
        t.allocate(available, allocation)
        allocation.child(0).nodes()*.id == ['1']
        allocation.child(1).nodes()*.id == ['1', '2']
        available.toString() == '{ 3 }'
    }
}
