package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

import static dolphin.core.CompletionState.Type.*

/**
 * Reference A.2 "T / { c } and until { c } run T" with the fixes: the child is stopped (not just
 * its hook called) and started lazily, at the first step whose check is false.
 */
@Timeout(30)
@Unroll
class ConstrainedTaskSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()
    int checks = 0

    static final Map<String, Closure<Task>> FORMS = [
            'T / { c }'        : { Task t, Condition c -> t / c },
            'until { c } run T': { Task t, Condition c -> new ConstrainedTask(t, c) },
    ]

    /** A condition that holds from the given clock time on, counting its evaluations. */
    Condition from(double seconds) {
        { -> checks++; d.now() >= seconds - 1e-9 } as Condition
    }

    def "the operator / with a closure builds a constrained task"() {
        given:
        boolean stop = false
        def t = Probe.lasting(journal, 'a', 1) / { stop }

        expect:
        t instanceof ConstrainedTask
    }

    def "#form: the condition is checked before each step; once it holds the task is stopped and the constraint is DONE"() {
        given:
        d.launch(FORMS[form].call(Probe.lasting(journal, 'a', 10), from(0.5)))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        d.time() == '0.5'
        journal.lines() == ['start a 1 @0', 'stop a 1 @0.5']
        journal.stepTimes('a') == ['0', '0.1', '0.2', '0.3', '0.4']
        checks == 6

        where:
        form << FORMS.keySet()
    }

    def "#form: a condition that holds at the first step never starts the task"() {
        given:
        d.launch(FORMS[form].call(Probe.lasting(journal, 'a', 10), from(0)))

        when:
        def cs = d.executor.step()

        then:
        cs == CompletionState.DONE
        d.executor.completed
        journal.lines('init') == ['init a 1 @0']
        journal.lines().empty
        journal.stepTimes('a').empty

        where:
        form << FORMS.keySet()
    }

    def "#form: the task is started at the first step, not when the constraint starts"() {
        given:
        d.launch(FORMS[form].call(Probe.lasting(journal, 'a', 10), from(5)))
        d.clock.advance(Environment.TICK)

        expect:
        journal.lines().empty

        when:
        d.executor.step()

        then:
        journal.lines() == ['start a 1 @0.1']
        journal.stepTimes('a') == ['0.1']

        where:
        form << FORMS.keySet()
    }

    def "#form: a task that ends by itself ends the constraint, and the condition is not checked again"() {
        given:
        d.launch(FORMS[form].call(Probe.lasting(journal, 'a', 0.3), from(5)))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        d.time() == '0.3'
        journal.lines() == ['start a 1 @0', 'done a 1 @0.3']
        checks == 4

        where:
        form << FORMS.keySet()
    }

    def "#form: an ERROR of the task is passed through"() {
        given:
        d.launch(FORMS[form].call(Probe.failing(journal, 'a', 0.2, 'stall'), from(5)))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('stall')
        journal.lines() == ['start a 1 @0', 'error a 1 @0.2']

        where:
        form << FORMS.keySet()
    }

    def "#form: while the condition is false the task's state is passed up"() {
        given:
        d.launch(FORMS[form].call(Probe.lasting(journal, 'a', 10), from(5)))

        expect:
        d.ticks(3) == [IN_PROGRESS, IN_PROGRESS, IN_PROGRESS]

        where:
        form << FORMS.keySet()
    }

    def "cutting a sequence stops its running part (E-11, F-15)"() {
        given:
        def seq = Probe.lasting(journal, 'a', 0.3) >> Probe.lasting(journal, 'b', 10)
        d.launch(seq / from(0.5))

        when:
        d.runToEnd()

        then:
        journal.lines() == ['start a 1 @0', 'done a 1 @0.3', 'start b 1 @0.3', 'stop b 1 @0.5']
    }

    def "cutting a concurrent task stops both running parts"() {
        given:
        d.launch((Probe.lasting(journal, 'a', 10) | Probe.lasting(journal, 'b', 10)) / from(0.2))

        when:
        d.runToEnd()

        then:
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'stop a 1 @0.2', 'stop b 2 @0.2']
    }

    def "stopping the constraint from outside stops the running task once"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 10) / from(5))
        d.ticks(3)

        when:
        d.executor.stop()
        d.executor.stop()

        then:
        journal.lines() == ['start a 1 @0', 'stop a 1 @0.3']
    }

    def "stopping the constraint before its first step sends nothing to the never-started task"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 10) / from(5))

        when:
        d.executor.stop()

        then:
        journal.lines().empty
        checks == 0
    }

    def "precedence: 'm / { c } >> r' is '(m / { c }) >> r' (A.3)"() {
        given:
        def m = Probe.lasting(journal, 'm', 10)
        def r = Probe.lasting(journal, 'r', 0.2)
        def t = m / { d.now() >= 0.5 - 1e-9 } >> r

        when:
        d.launch(t)
        d.runToEnd()

        then:
        t instanceof SequentialTask
        journal.lines() == ['start m 1 @0', 'stop m 1 @0.5', 'start r 1 @0.5', 'done r 1 @0.7']
    }

    def "the constraint allocates what its task needs"() {
        given:
        def available = d.all()
        def allocation = new Allocation()

        expect:
        (Probe.lasting(journal, 'a', 1, 2) / from(1)).allocate(available, allocation)
        available.toString() == '{ 3 }'
        allocation.allNodes()*.id == ['1', '2']
    }
}
