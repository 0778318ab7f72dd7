package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

import static dolphin.core.CompletionState.Type.*

/** Reference A.2 "idle secs". */
@Timeout(30)
class IdleTaskSpec extends Specification {

    Driver d = new Driver()

    def "idle 0 is DONE at its first step"() {
        given:
        d.launch(new IdleTask(0))

        expect:
        d.executor.step() == CompletionState.DONE
        d.executor.completed
    }

    def "idle 0.25 is DONE at the 0.3 s tick"() {
        given:
        d.launch(new IdleTask(0.25))

        expect:
        d.ticks(4) == [IN_PROGRESS, IN_PROGRESS, IN_PROGRESS, DONE]
        d.executor.completed
    }

    @Unroll
    def "idle #seconds is DONE at the first tick at or after it: #end s"() {
        given:
        d.launch(new IdleTask(seconds))

        when:
        d.runToEnd()

        then:
        d.time() == end

        where:
        seconds || end
        0.1     || '0.1'
        0.25    || '0.3'
        1       || '1'
        2.05    || '2.1'
        10      || '10'
    }

    def "idle needs no vehicle and takes none"() {
        given:
        def available = d.all()
        def allocation = new Allocation()

        expect:
        new IdleTask(1).allocate(available, allocation)
        available.size() == 3
        allocation.allNodes().empty
        new IdleTask(1).allocate(new NodeSet(), new Allocation())
    }

    def "idle under the Environment waits in virtual time"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def env = new Environment(d.platform, clock, new RecordingListener())

        when:
        def cs = env.run(new IdleTask(0.25))

        then:
        cs == CompletionState.DONE
        Math.abs(clock.seconds() - 0.3d) < 1e-9
    }

    @Unroll
    def "idle #seconds is rejected"() {
        when:
        new IdleTask(seconds)

        then:
        thrown(EnvironmentException)

        where:
        seconds << [-1d, -0.001d, Double.NaN]
    }
}
