package dolphin.core

import dolphin.testing.FlyTask
import dolphin.testing.TestNode
import dolphin.testing.TestPlatform
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

import java.time.Duration

/** Reference A.2 (pick, execute, release, setConnectionTimeout), B.2, B.3 and design §7 (ticks and wake-ups). */
@Timeout(30)
class EnvironmentSpec extends Specification {

    static final Position APDL = Position.fromDegrees(41.185781, -8.70606486, 0)
    static final Position B1 = Position.fromDegrees(41.184742, -8.704601, 0)
    static final Position B2 = Position.fromDegrees(41.186057, -8.706045, 0)

    /** A test platform that counts pick attempts (each attempt reads the connected nodes once). */
    static class CountingPlatform extends TestPlatform {
        int reads

        @Override
        NodeSet getConnectedNodes() {
            reads++
            super.getConnectedNodes()
        }
    }

    ManualClock clock = ManualClock.autoAdvancing()
    CountingPlatform platform = new CountingPlatform()
    RecordingListener listener = new RecordingListener()
    Environment env = new Environment(platform, clock, listener)

    void fourVehicles() {
        platform.addNode('1', 'UAV', APDL, [])
        platform.addNode('2', 'UAV', B1, ['camera'])
        platform.addNode('3', 'UGV', B2, ['camera', 'sonar'])
        platform.addNode('4', 'UAV', Position.fromDegrees(41.185781, -8.70606486, 500), [])
    }

    static NodeFilter filter(Map m) {
        new NodeFilter(m.id as String, m.type as String, (m.payload ?: []) as List<String>, m.area as Area)
    }

    void at(double seconds, Closure change) {
        clock.schedule(Duration.ofNanos(Math.round(seconds * 1e9)), change as Runnable)
    }

    static boolean near(double a, double b) { Math.abs(a - b) < 1e-9 }

    // ---- pick

    @Unroll
    def "pick #count with #clauses chooses #expected"() {
        given:
        fourVehicles()

        when:
        def chosen = env.select(filter(clauses), count, 0)

        then:
        chosen.ids() == expected
        env.bound.ids() == expected

        where:
        clauses                                  | count || expected
        [:]                                      | 1     || ['1']
        [:]                                      | 2     || ['1', '2']
        [:]                                      | 4     || ['1', '2', '3', '4']
        [id: '3']                                | 1     || ['3']
        [type: 'UGV']                            | 1     || ['3']
        [type: 'UAV']                            | 3     || ['1', '2', '4']
        [payload: ['camera']]                    | 1     || ['2']
        [payload: ['camera']]                    | 2     || ['2', '3']
        [payload: ['camera', 'sonar']]           | 1     || ['3']
        [area: new Area(APDL, 100)]              | 2     || ['1', '3']
        [area: new Area(APDL, 200)]              | 3     || ['1', '2', '3']
        [area: new Area(APDL, 499)]              | 3     || ['1', '2', '3']
        [area: new Area(APDL, 501)]              | 4     || ['1', '2', '3', '4']
        [type: 'UAV', area: new Area(APDL, 100)] | 1     || ['1']
        [type: 'UAV', payload: ['camera']]       | 1     || ['2']
    }

    @Unroll
    def "pick #count with #clauses finds nothing and returns NodeSet.EMPTY itself"() {
        given:
        fourVehicles()

        when:
        def chosen = env.select(filter(clauses), count, 0)

        then:
        chosen.is(NodeSet.EMPTY)
        env.bound.empty

        where:
        clauses                                  | count
        [:]                                      | 5
        [id: '9']                                | 1
        [id: '3']                                | 2
        [type: 'USV']                            | 1
        [type: 'UGV']                            | 2
        [payload: ['lidar']]                     | 1
        [payload: ['camera', 'lidar']]           | 1
        [area: new Area(APDL, 100)]              | 3
        [type: 'UGV', area: new Area(APDL, 10)]  | 1
    }

    def "the first matches in platform order are chosen"() {
        given:
        ['3', '1', '2'].each { platform.addNode(it) }

        expect:
        env.select(NodeFilter.ANY, 2, 0).ids() == ['3', '1']
    }

    def "bound vehicles are not picked again until released; release sends nothing to them"() {
        given:
        ['1', '2'].each { platform.addNode(it) }

        when:
        def v1 = env.select(NodeFilter.ANY, 1, 0)
        def v2 = env.select(NodeFilter.ANY, 1, 0)
        def v3 = env.select(NodeFilter.ANY, 1, 0)

        then:
        v1.ids() == ['1']
        v2.ids() == ['2']
        v3.is(NodeSet.EMPTY)

        when:
        env.release(v1)

        then:
        env.bound.ids() == ['2']
        platform.node('1').releases.empty
        env.select(NodeFilter.ANY, 1, 0).ids() == ['1']
    }

    def "vehicles that are not connected cannot be picked"() {
        given:
        ['1', '2'].each { platform.addNode(it) }
        platform.node('1').connected = false

        expect:
        env.select(NodeFilter.ANY, 1, 0).ids() == ['2']
        env.select(NodeFilter.ANY, 1, 0).is(NodeSet.EMPTY)
    }

    @Unroll
    def "pick with timeout #timeout and a vehicle appearing at #appears s: #outcome at #end s after #attempts attempts"() {
        given:
        if (appears != null) {
            at(appears) { platform.addNode('1') }
        }

        when:
        def chosen = env.select(NodeFilter.ANY, 1, timeout)

        then:
        chosen.ids() == (outcome == 'found' ? ['1'] : [])
        (outcome == 'found') != chosen.is(NodeSet.EMPTY)
        near(clock.seconds(), end)
        platform.reads == attempts

        where:
        timeout | appears || outcome | end  | attempts
        0       | null    || 'none'  | 0    | 1
        0       | 0.5     || 'none'  | 0    | 1
        0.5     | null    || 'none'  | 1    | 2
        5       | null    || 'none'  | 5    | 6
        5       | 3.5     || 'found' | 4    | 5
        10      | 9.5     || 'found' | 10   | 11
        20      | 5       || 'found' | 6    | 4
        30      | null    || 'none'  | 30   | 11
        30      | 7       || 'found' | 9    | 4
        100     | 25      || 'found' | 30   | 4
    }

    @Unroll
    def "pick rejects count #count and timeout #timeout"() {
        given:
        platform.addNode('1')

        when:
        env.select(NodeFilter.ANY, count, timeout)

        then:
        thrown(EnvironmentException)
        env.bound.empty

        where:
        count | timeout
        0     | 0
        -1    | 0
        1     | -1
        1     | -0.5
        1     | Double.NaN
    }

    def "picked vehicles get the current default connection timeout"() {
        given:
        ['1', '2', '3'].each { platform.addNode(it).connectionTimeout = 100 }

        when:
        env.select(NodeFilter.ANY, 1, 0)
        env.defaultConnectionTimeout = 60
        env.select(NodeFilter.ANY, 1, 0)

        then:
        env.defaultConnectionTimeout == 60
        platform.node('1').connectionTimeout == Node.DEFAULT_CONNECTION_TIMEOUT
        Node.DEFAULT_CONNECTION_TIMEOUT == 20
        platform.node('2').connectionTimeout == 60
        platform.node('3').connectionTimeout == 100
    }

    @Unroll
    def "a connection timeout of #seconds s is #verdict"() {
        given:
        def node = platform.addNode('1')

        when:
        def results = [
                { env.defaultConnectionTimeout = seconds },
                { node.connectionTimeout = seconds },
                { Node.validateConnectionTimeout(seconds) },
        ].collect {
            try {
                it.call()
                'ok'
            } catch (EnvironmentException e) {
                'rejected'
            }
        }

        then:
        results == [verdict] * 3
        env.defaultConnectionTimeout == (verdict == 'ok' ? seconds : 20d)
        node.connectionTimeout == (verdict == 'ok' ? seconds : 20d)

        where:
        seconds         || verdict
        5d              || 'ok'
        20d             || 'ok'
        3600d           || 'ok'
        4.99d           || 'rejected'
        0d              || 'rejected'
        -10d            || 'rejected'
        3600.5d         || 'rejected'
        Double.NaN      || 'rejected'
        Double.POSITIVE_INFINITY || 'rejected'
    }

    def "releaseAll calls release() on every bound vehicle, once, and unbinds them all"() {
        given:
        ['1', '2', '3'].each { platform.addNode(it) }
        env.select(NodeFilter.ANY, 2, 0)

        when:
        env.releaseAll()

        then:
        platform.node('1').releases == ['1']
        platform.node('2').releases == ['2']
        platform.node('3').releases.empty
        env.bound.empty
        env.select(NodeFilter.ANY, 3, 0).ids() == ['1', '2', '3']
    }

    def "a vehicle whose release fails does not keep the others bound"() {
        given:
        def good = platform.addNode('2')
        def bad = new TestNode(platform, '1', 'UAV', Payload.NONE, APDL) {
            @Override
            void release() { throw new IllegalStateException('socket closed') }
        }
        def both = new TestPlatform() {
            @Override
            NodeSet getConnectedNodes() { NodeSet.of(bad, good) }
        }
        def env2 = new Environment(both, clock, listener)
        env2.select(NodeFilter.ANY, 2, 0)

        when:
        env2.releaseAll()

        then:
        good.releases == ['2']
        env2.bound.empty
        listener.messages.any { it.contains('releasing vehicle 1 failed') && it.contains('socket closed') }
    }

    // ---- run

    def "run uses only the bound vehicles"() {
        given:
        ['1', '2', '3'].each { platform.addNode(it) }
        env.select(filter(id: '2'), 1, 0)

        when:
        def cs = env.run(new FlyTask(platform, 'survey', 1))

        then:
        cs == CompletionState.DONE
        platform.journal*.toString() == ['start survey 2 @0.0', 'done survey 2 @1.0']
    }

    def "run without enough bound vehicles throws 'no vehicles to run task' and starts nothing"() {
        given:
        ['1', '2'].each { platform.addNode(it) }
        env.select(NodeFilter.ANY, 1, 0)

        when:
        env.run(new FlyTask(platform, 'a', 1) | new FlyTask(platform, 'b', 1))

        then:
        def e = thrown(EnvironmentException)
        e.message.contains('no vehicles to run task')
        platform.journal.empty
    }

    def "a task needing no vehicle runs with nothing bound"() {
        expect:
        env.run(new IdleTask(0.5)) == CompletionState.DONE
        near(clock.seconds(), 0.5)
    }

    def "the root is stepped at once and then every 100 ms"() {
        given:
        List<Double> steps = []

        when:
        env.run(new ConditionTask({ steps << clock.seconds(); clock.seconds() >= 0.5 - 1e-9 } as Condition))

        then:
        Environment.TICK == Duration.ofMillis(100)
        steps.collect { Journal.fmt(it) } == ['0', '0.1', '0.2', '0.3', '0.4', '0.5']
    }

    def "a vehicle that loses its link fails its task with an ERROR naming it, as soon as the loss is known"() {
        given:
        ['1', '2'].each { platform.addNode(it) }
        env.select(filter(id: '2'), 1, 0)
        at(2.05) { platform.node('2').connected = false }

        when:
        def cs = env.run(new FlyTask(platform, 'survey', 100))

        then:
        cs.error
        cs.message.startsWith('vehicle 2 lost')
        cs.message.contains('20 s')
        near(clock.seconds(), 2.05)
        platform.journal*.toString() == ['start survey 2 @0.0', 'error survey 2 @2.05']
        listener.messages.any { it.startsWith('task survey ended in ERROR: vehicle 2 lost') }
    }

    def "wake() steps the tree before the next tick"() {
        given:
        boolean go = false
        at(0.05) { go = true; env.wake() }

        when:
        env.run(new ConditionTask({ go } as Condition))

        then:
        near(clock.seconds(), 0.05)
    }

    def "a change without wake() is seen at the next tick"() {
        given:
        boolean go = false
        at(0.05) { go = true }

        when:
        env.run(new ConditionTask({ go } as Condition))

        then:
        near(clock.seconds(), 0.1)
    }

    def "telemetry from a test vehicle wakes the runtime"() {
        given:
        def n = platform.addNode('1')
        env.select(NodeFilter.ANY, 1, 0)
        at(1.234) { n.battery = 0.2 }

        when:
        env.run(new FlyTask(platform, 'survey', 100) / { n.batteryRemaining() < 0.3 })

        then:
        near(clock.seconds(), 1.234)
        platform.journal*.toString() == ['start survey 1 @0.0', 'stop survey 1 @1.234']
    }

    def "a wake-up adds a step but does not shift or skip the 100 ms ticks"() {
        given:
        List<String> steps = []
        at(0.05) { env.wake() }
        at(0.25) { env.wake() }

        when:
        env.run(new ConditionTask({ steps << Journal.fmt(clock.seconds()); clock.seconds() >= 0.4 - 1e-9 } as Condition))

        then:
        steps == ['0', '0.05', '0.1', '0.2', '0.25', '0.3', '0.4']
    }

    def "after a burst of wake-ups the tree is still stepped every 100 ms"() {
        given: 'telemetry every 10 ms for 2 s, then silence'
        for (int i = 1; i <= 200; i++) {
            at(i * 0.01) { env.wake() }
        }

        when:
        def cs = env.run(new TimeConstrainedTask(new ConditionTask({ false } as Condition), 3))

        then:
        cs == CompletionState.DONE
        near(clock.seconds(), 3.0)
    }
}
