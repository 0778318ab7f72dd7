package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.core.CompletionState.Type.*

/** Reference A.2 "T1 | T2" and A.4 (concurrent row). */
@Timeout(30)
class ConcurrentTaskSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()

    def "the operator | builds a concurrent task"() {
        expect:
        (Probe.lasting(journal, 'a', 1) | Probe.lasting(journal, 'b', 1)) instanceof ConcurrentTask
    }

    def "both parts start at once, on distinct vehicles"() {
        when:
        d.launch(Probe.lasting(journal, 'a', 1) | Probe.lasting(journal, 'b', 1))

        then:
        journal.lines() == ['start a 1 @0', 'start b 2 @0']
    }

    def "it is DONE when both parts are DONE; a finished part is not stepped again"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 0.2) | Probe.lasting(journal, 'b', 0.4))

        when:
        def states = d.ticks(5)

        then:
        states == [IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, DONE]
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'done a 1 @0.2', 'done b 2 @0.4']
        journal.stepTimes('a') == ['0', '0.1', '0.2']
        journal.stepTimes('b') == ['0', '0.1', '0.2', '0.3', '0.4']
    }

    def "in each tick the first part is stepped before the second"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 1) | Probe.lasting(journal, 'b', 1))

        when:
        d.ticks(3)

        then:
        journal.lines('step') == ['step a 1 @0', 'step b 2 @0', 'step a 1 @0.1', 'step b 2 @0.1', 'step a 1 @0.2', 'step b 2 @0.2']
    }

    def "an ERROR of the first part ends it at once and stops the second"() {
        given:
        d.launch(Probe.failing(journal, 'a', 0.3, 'battery critical') | Probe.lasting(journal, 'b', 1))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('battery critical')
        d.time() == '0.3'
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'error a 1 @0.3', 'stop b 2 @0.3']
    }

    def "an ERROR of the second part ends it at once and stops the first"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 1) | Probe.failing(journal, 'b', 0.3, 'link lost'))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('link lost')
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'error b 2 @0.3', 'stop a 1 @0.3']
    }

    def "when both fail in the same tick the first part's error is the result and the second is stopped"() {
        given:
        d.launch(Probe.failing(journal, 'a', 0.2, 'first') | Probe.failing(journal, 'b', 0.2, 'second'))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('first')
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'error a 1 @0.2', 'stop b 2 @0.2']
    }

    def "a part that already ended is not stopped when the other fails"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 0.1) | Probe.failing(journal, 'b', 0.3, 'boom'))

        when:
        def cs = d.runToEnd()

        then:
        cs.error
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'done a 1 @0.1', 'error b 2 @0.3']
    }

    def "three parts run on three vehicles and the whole ends with the last"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 0.3) | Probe.lasting(journal, 'b', 0.1) | Probe.lasting(journal, 'c', 0.2))

        when:
        def cs = d.runToEnd()

        then:
        cs.done
        d.time() == '0.3'
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'start c 3 @0', 'done b 2 @0.1', 'done c 3 @0.2', 'done a 1 @0.3']
    }

    def "it cannot be allocated when there are fewer free vehicles than parts"() {
        given:
        def t = Probe.lasting(journal, 'a', 1) | Probe.lasting(journal, 'b', 1)

        expect:
        !t.allocate(d.set('1'), new Allocation())
        t.allocate(d.set('1', '2'), new Allocation())
    }
}
