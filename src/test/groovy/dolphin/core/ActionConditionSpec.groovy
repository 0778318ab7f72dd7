package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.core.CompletionState.Type.*

/** Reference A.2 "action { code } / condition { c }". */
@Timeout(30)
class ActionConditionSpec extends Specification {

    Driver d = new Driver()

    def "an action runs its code once, at its first step, and is then DONE"() {
        given:
        int runs = 0
        def t = new ActionTask({ runs++ } as Runnable)
        def ex = t.executor

        when:
        ex.initialize(d.context, new Allocation())
        ex.start()

        then:
        runs == 0

        when:
        def cs = ex.step()

        then:
        cs == CompletionState.DONE
        ex.completed
        runs == 1
    }

    def "an action in a sequence runs when its turn comes"() {
        given:
        List<String> ranAt = []
        d.launch(new IdleTask(0.2) >> new ActionTask({ ranAt << d.time() } as Runnable))

        when:
        d.runToEnd()

        then:
        ranAt == ['0.2']
    }

    def "an exception from the action's code comes out of the step"() {
        given:
        d.launch(new ActionTask({ throw new IllegalStateException('bad code') } as Runnable))

        when:
        d.executor.step()

        then:
        def e = thrown(IllegalStateException)
        e.message == 'bad code'
    }

    def "a condition is IN_PROGRESS until it holds, re-evaluated at every step, then DONE"() {
        given:
        int checks = 0
        d.launch(new ConditionTask({ checks++; d.now() >= 0.4 - 1e-9 } as Condition))

        expect:
        d.ticks(5) == [IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, DONE]
        checks == 5
        d.executor.completed
    }

    def "a condition that already holds is DONE at its first step"() {
        given:
        d.launch(new ConditionTask({ true } as Condition))

        expect:
        d.executor.step() == CompletionState.DONE
    }

    def "a condition follows a value another party changes"() {
        given:
        boolean signal = false
        d.launch(new ConditionTask({ signal } as Condition))

        expect:
        d.ticks(3) == [IN_PROGRESS, IN_PROGRESS, IN_PROGRESS]

        when:
        signal = true

        then:
        d.tick() == CompletionState.DONE
    }

    def "neither needs a vehicle"() {
        given:
        def available = d.all()
        def allocation = new Allocation()

        expect:
        new ActionTask({} as Runnable).allocate(available, allocation)
        new ConditionTask({ true } as Condition).allocate(available, allocation)
        available.size() == 3
        allocation.allNodes().empty
        new ActionTask({} as Runnable).allocate(new NodeSet(), new Allocation())
    }
}
