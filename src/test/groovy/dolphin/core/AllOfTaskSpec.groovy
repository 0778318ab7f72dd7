package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.core.CompletionState.Type.*

/** Reference A.2 "allOf", F-12: branches run one at a time, each when its guard is the first remaining true one. */
@Timeout(30)
class AllOfTaskSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()
    Map<String, Integer> checks = [:].withDefault { 0 }

    TaskGuard when(String name, double from, Task task) {
        new TaskGuard({ -> checks[name]++; d.now() >= from - 1e-9 } as Condition, task)
    }

    /** True when no two branches were running at the same time. */
    boolean oneAtATime() {
        int running = 0
        for (e in journal.entries) {
            if (e.kind == 'start') {
                if (++running > 1) {
                    return false
                }
            } else if (e.kind in ['done', 'error', 'stop']) {
                running--
            }
        }
        true
    }

    def "with all guards true the branches run one at a time, in declaration order, and then allOf is DONE"() {
        given:
        d.launch(new AllOfTask([when('a', 0, Probe.lasting(journal, 'a', 0.3)),
                                when('b', 0, Probe.lasting(journal, 'b', 0.2)),
                                when('c', 0, Probe.lasting(journal, 'c', 0.1))]))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        journal.lines() == ['start a 1 @0', 'done a 1 @0.3', 'start b 1 @0.4', 'done b 1 @0.6', 'start c 1 @0.7', 'done c 1 @0.8']
        d.time() == '0.8'
        oneAtATime()
    }

    def "a branch is started and stepped in the tick its guard is found true"() {
        given:
        d.launch(new AllOfTask([when('a', 0.2, Probe.lasting(journal, 'a', 0.1))]))

        when:
        d.runToEnd()

        then:
        journal.stepTimes('a') == ['0.2', '0.3']
        journal.lines() == ['start a 1 @0.2', 'done a 1 @0.3']
    }

    def "the first remaining guard that holds wins, whatever the declaration order of the rest"() {
        given:
        d.launch(new AllOfTask([when('a', 1.0, Probe.lasting(journal, 'a', 0.2)),
                                when('b', 0, Probe.lasting(journal, 'b', 0.2))]))

        when:
        def cs = d.runToEnd()

        then:
        cs.done
        journal.lines() == ['start b 1 @0', 'done b 1 @0.2', 'start a 1 @1', 'done a 1 @1.2']
        oneAtATime()
    }

    def "when several remaining guards hold, the earliest declared one runs next"() {
        given:
        d.launch(new AllOfTask([when('a', 0.5, Probe.lasting(journal, 'a', 0.1)),
                                when('b', 0.5, Probe.lasting(journal, 'b', 0.1)),
                                when('c', 0, Probe.lasting(journal, 'c', 0.6))]))

        when:
        d.runToEnd()

        then:
        journal.lines('start') == ['start c 1 @0', 'start a 1 @0.7', 'start b 1 @0.9']
    }

    def "guards are not checked while a branch runs, and a branch's guard is not checked once it ran"() {
        given:
        d.launch(new AllOfTask([when('a', 0, Probe.lasting(journal, 'a', 0.3)),
                                when('b', 0, Probe.lasting(journal, 'b', 0.3))]))

        when:
        d.runToEnd()

        then:
        checks == [a: 1, b: 1]
    }

    def "allOf stays IN_PROGRESS while no remaining guard holds"() {
        given:
        d.launch(new AllOfTask([when('a', 0, Probe.lasting(journal, 'a', 0.1)),
                                when('b', 9, Probe.lasting(journal, 'b', 0.1))]))

        expect:
        d.ticks(10).every { it == IN_PROGRESS }
        journal.lines() == ['start a 1 @0', 'done a 1 @0.1']
    }

    def "an ERROR of a branch ends allOf at once; later branches never start"() {
        given:
        d.launch(new AllOfTask([when('a', 0, Probe.lasting(journal, 'a', 0.1)),
                                when('b', 0, Probe.failing(journal, 'b', 0.2, 'no fuel')),
                                when('c', 0, Probe.lasting(journal, 'c', 0.1))]))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('no fuel')
        d.time() == '0.4'
        journal.lines() == ['start a 1 @0', 'done a 1 @0.1', 'start b 1 @0.2', 'error b 1 @0.4']
    }

    def "stopping allOf stops the running branch only; branches not yet run are never started"() {
        given:
        d.launch(new AllOfTask([when('a', 0, Probe.lasting(journal, 'a', 0.1)),
                                when('b', 0, Probe.lasting(journal, 'b', 5)),
                                when('c', 0, Probe.lasting(journal, 'c', 5))]))
        d.ticks(5)

        when:
        d.executor.stop()

        then:
        journal.lines() == ['start a 1 @0', 'done a 1 @0.1', 'start b 1 @0.2', 'stop b 1 @0.5']
    }

    def "allOf without branches is rejected"() {
        when:
        new AllOfTask([])

        then:
        def e = thrown(EnvironmentException)
        e.message.contains('no choices')
    }

    def "every branch allocates from its own copy of the pool; all vehicles used are taken (A.4)"() {
        given:
        def available = d.all()
        def allocation = new Allocation()
        def t = new AllOfTask([when('a', 0, Probe.lasting(journal, 'a', 1)),
                               when('b', 0, Probe.lasting(journal, 'b', 1)[d.set('2')])])

        expect:
        t.allocate(available, allocation)
        allocation.allNodes()*.id == ['1', '2']
        available.toString() == '{ 3 }'
    }
}
