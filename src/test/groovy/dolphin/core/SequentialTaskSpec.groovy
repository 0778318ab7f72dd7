package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.core.CompletionState.Type.*

/** Reference A.2 "T1 >> T2", A.4 (sequence row) and the E-11 fix. */
@Timeout(30)
class SequentialTaskSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()

    def "the operator >> builds a sequence"() {
        given:
        def a = Probe.lasting(journal, 'a', 1)
        def b = Probe.lasting(journal, 'b', 1)

        expect:
        (a >> b) instanceof SequentialTask
    }

    def "both parts are initialised up front but only the first is started"() {
        given:
        def a = Probe.lasting(journal, 'a', 1)
        def b = Probe.lasting(journal, 'b', 1)

        when:
        d.launch(a >> b)

        then:
        journal.lines('init') == ['init a 1 @0', 'init b 1 @0']
        journal.lines() == ['start a 1 @0']
    }

    def "while the first part runs its state is passed up and the second part is not stepped"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 0.3) >> Probe.lasting(journal, 'b', 1))

        when:
        def states = d.ticks(3)

        then:
        states == [IN_PROGRESS, IN_PROGRESS, IN_PROGRESS]
        journal.stepTimes('a') == ['0', '0.1', '0.2']
        journal.stepTimes('b').empty
    }

    def "the second part starts and is stepped in the very tick in which the first is DONE"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 0.3) >> Probe.lasting(journal, 'b', 0.2))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        d.time() == '0.5'
        journal.lines() == ['start a 1 @0', 'done a 1 @0.3', 'start b 1 @0.3', 'done b 1 @0.5']
        journal.stepTimes('b') == ['0.3', '0.4', '0.5']
        journal.stepTimes('a') == ['0', '0.1', '0.2', '0.3']
    }

    def "two parts that end at once finish the sequence in a single step"() {
        given:
        d.launch(new IdleTask(0) >> new IdleTask(0))

        expect:
        d.executor.step() == CompletionState.DONE
        d.executor.completed
        d.now() == 0d
    }

    def "an ERROR of the first part ends the sequence with that error; the second part never starts"() {
        given:
        d.launch(Probe.failing(journal, 'a', 0.2, 'engine failure') >> Probe.lasting(journal, 'b', 1))

        when:
        def cs = d.runToEnd()

        then:
        cs.error
        cs.message == 'engine failure'
        d.time() == '0.2'
        journal.lines() == ['start a 1 @0', 'error a 1 @0.2']
    }

    def "an ERROR of the second part is the sequence's result"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 0.1) >> Probe.failing(journal, 'b', 0.2, 'gps lost'))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('gps lost')
        d.time() == '0.3'
        journal.lines() == ['start a 1 @0', 'done a 1 @0.1', 'start b 1 @0.1', 'error b 1 @0.3']
    }

    def "both parts may use the same vehicle"() {
        given:
        def d1 = new Driver(1)

        when:
        d1.launch(Probe.lasting(journal, 'a', 0.1) >> Probe.lasting(journal, 'b', 0.1))
        d1.runToEnd()

        then:
        journal.lines() == ['start a 1 @0', 'done a 1 @0.1', 'start b 1 @0.1', 'done b 1 @0.2']
    }

    def "stopping a sequence while its first part runs stops that part only (E-11)"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 1) >> Probe.lasting(journal, 'b', 1))
        d.ticks(5)

        when:
        d.executor.stop()

        then:
        journal.lines() == ['start a 1 @0', 'stop a 1 @0.5']
    }

    def "stopping a sequence while its second part runs stops the second part (E-11)"() {
        given:
        d.launch(Probe.lasting(journal, 'a', 0.2) >> Probe.lasting(journal, 'b', 1))
        d.ticks(5)

        when:
        d.executor.stop()

        then:
        journal.lines() == ['start a 1 @0', 'done a 1 @0.2', 'start b 1 @0.2', 'stop b 1 @0.5']
    }

    def "a longer chain runs its parts one after the other, each starting when the previous is DONE"() {
        given:
        def a = Probe.lasting(journal, 'a', 0.2)
        def b = Probe.lasting(journal, 'b', 0.1)
        def c = Probe.lasting(journal, 'c', 0.3)

        when:
        d.launch(a >> b >> c)
        def cs = d.runToEnd()

        then:
        cs.done
        journal.lines() == ['start a 1 @0', 'done a 1 @0.2', 'start b 1 @0.2', 'done b 1 @0.3',
                            'start c 1 @0.3', 'done c 1 @0.6']
    }
}
