package dolphin.core

import dolphin.testing.FlyTask
import dolphin.testing.TestPlatform
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

/** Reference A.2 "during { secs } run T" with the stop fix (F-15) and lazy start. */
@Timeout(30)
class TimeConstrainedTaskSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()

    @Unroll
    def "during #seconds s ends at the first 100 ms tick at or after #seconds s, at #end s"() {
        given:
        d.launch(new TimeConstrainedTask(Probe.lasting(journal, 'a', 100), seconds))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        d.time() == end
        journal.lines() == ['start a 1 @0', "stop a 1 @${end}"]

        where:
        seconds || end
        0.05    || '0.1'
        0.3     || '0.3'
        1       || '1'
        1.25    || '1.3'
        2.01    || '2.1'
    }

    def "during 1.25 s run under the Environment stops a flying task at the 1.3 s tick"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def platform = new TestPlatform()
        platform.addNode('1')
        def env = new Environment(platform, clock, new RecordingListener())
        env.select(NodeFilter.ANY, 1, 0)

        when:
        def cs = env.run(new TimeConstrainedTask(new FlyTask(platform, 'survey', 100), 1.25))

        then:
        cs == CompletionState.DONE
        Math.abs(clock.seconds() - 1.3d) < 1e-9
        platform.journal*.toString() == ['start survey 1 @0.0', 'stop survey 1 @1.3']
    }

    def "during 0 never starts its task"() {
        given:
        d.launch(new TimeConstrainedTask(Probe.lasting(journal, 'a', 100), 0))

        expect:
        d.executor.step() == CompletionState.DONE
        journal.lines().empty
    }

    def "a task that ends before the time is up ends the constraint with its state"() {
        given:
        d.launch(new TimeConstrainedTask(Probe.lasting(journal, 'a', 0.4), 5))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        d.time() == '0.4'
        journal.lines() == ['start a 1 @0', 'done a 1 @0.4']
    }

    def "an ERROR of the task is passed through"() {
        given:
        d.launch(new TimeConstrainedTask(Probe.failing(journal, 'a', 0.4, 'lost GPS'), 5))

        expect:
        d.runToEnd() == CompletionState.error('lost GPS')
        journal.lines() == ['start a 1 @0', 'error a 1 @0.4']
    }

    def "the time counts from the start of the constraint, not of the whole tree"() {
        given:
        d.launch(new IdleTask(1) >> new TimeConstrainedTask(Probe.lasting(journal, 'a', 100), 0.5))

        when:
        d.runToEnd()

        then:
        d.time() == '1.5'
        journal.lines() == ['start a 1 @1', 'stop a 1 @1.5']
    }

    def "when the time is up a running sequence inside is stopped at its running part"() {
        given:
        d.launch(new TimeConstrainedTask(Probe.lasting(journal, 'a', 0.2) >> Probe.lasting(journal, 'b', 100), 0.6))

        when:
        d.runToEnd()

        then:
        journal.lines() == ['start a 1 @0', 'done a 1 @0.2', 'start b 1 @0.2', 'stop b 1 @0.6']
    }

    @Unroll
    def "a duration of #seconds is rejected"() {
        when:
        new TimeConstrainedTask(Probe.lasting(journal, 'a', 1), seconds)

        then:
        thrown(EnvironmentException)

        where:
        seconds << [-0.1d, -5d, Double.NaN]
    }
}
