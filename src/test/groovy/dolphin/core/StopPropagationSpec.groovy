package dolphin.core

import dolphin.testing.FlyTask
import dolphin.testing.TestPlatform
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

/**
 * Stopping (F-15, E-11, E-21): a stop reaches every running task below, exactly once; tasks that
 * never started hear nothing; tasks that already ended are left alone. Every tree is stopped at 0.5 s.
 */
@Timeout(30)
class StopPropagationSpec extends Specification {

    static class Kit {
        final Driver d = new Driver()
        final Journal journal = new Journal()
        int guardChecks

        Probe fly(String id, double seconds) { Probe.lasting(journal, id, seconds) }

        TaskGuard when(boolean holds, Task t) { new TaskGuard({ -> guardChecks++; holds } as Condition, t) }
    }

    @Unroll
    def "stopping #tree at 0.5 s: #lines"() {
        given:
        def kit = new Kit()
        kit.d.launch(build.call(kit) as Task)
        kit.d.ticks(5)

        when:
        kit.d.executor.stop()

        then:
        kit.journal.lines() == lines
        kit.journal.entries.every { it.time <= 0.5 }

        where:
        tree                          | build                                                                              || lines
        'a >> b, in a'                | { Kit k -> return k.fly('a', 9) >> k.fly('b', 9) }                                 || ['start a 1 @0', 'stop a 1 @0.5']
        'a >> b, in b'                | { Kit k -> return k.fly('a', 0.2) >> k.fly('b', 9) }                               || ['start a 1 @0', 'done a 1 @0.2', 'start b 1 @0.2', 'stop b 1 @0.5']
        'a | b'                       | { Kit k -> k.fly('a', 9) | k.fly('b', 9) }                                         || ['start a 1 @0', 'start b 2 @0', 'stop a 1 @0.5', 'stop b 2 @0.5']
        'a | b, a done'               | { Kit k -> k.fly('a', 0.2) | k.fly('b', 9) }                                       || ['start a 1 @0', 'start b 2 @0', 'done a 1 @0.2', 'stop b 2 @0.5']
        'a / { false }'               | { Kit k -> k.fly('a', 9) / ({ false } as Condition) }                              || ['start a 1 @0', 'stop a 1 @0.5']
        'during 9 run a'              | { Kit k -> new TimeConstrainedTask(k.fly('a', 9), 9) }                             || ['start a 1 @0', 'stop a 1 @0.5']
        'watch a'                     | { Kit k -> new WatcherTask(k.fly('a', 9), { ErrorHandler.Decision.IGNORE } as ErrorHandler) } || ['start a 1 @0', 'stop a 1 @0.5']
        'oneOf, chosen'               | { Kit k -> new ChoiceTask([k.when(false, k.fly('a', 9)), k.when(true, k.fly('b', 9))]) } || ['start b 1 @0', 'stop b 1 @0.5']
        'oneOf, nothing chosen'       | { Kit k -> new ChoiceTask([k.when(false, k.fly('a', 9)), k.when(false, k.fly('b', 9))]) } || []
        'allOf, second running'       | { Kit k -> new AllOfTask([k.when(true, k.fly('a', 0.1)), k.when(true, k.fly('b', 9)), k.when(true, k.fly('c', 9))]) } || ['start a 1 @0', 'done a 1 @0.1', 'start b 1 @0.2', 'stop b 1 @0.5']
        'a[{ 3 }]'                    | { Kit k -> k.fly('a', 9)[k.d.set('3')] }                                           || ['start a 3 @0', 'stop a 3 @0.5']
        '((a >> b) | c) / { false }'  | { Kit k -> return ((k.fly('a', 0.1) >> k.fly('b', 9)) | k.fly('c', 9)) / ({ false } as Condition) } || ['start a 1 @0', 'start c 2 @0', 'done a 1 @0.1', 'start b 1 @0.1', 'stop b 1 @0.5', 'stop c 2 @0.5']
        'idle 9 >> a'                 | { Kit k -> return new IdleTask(9) >> k.fly('a', 9) }                               || []
    }

    def "a choice stopped before anything was chosen does not evaluate its guards (E-21)"() {
        given:
        def kit = new Kit()
        kit.d.launch(new ChoiceTask([kit.when(false, kit.fly('a', 9)), kit.when(false, kit.fly('b', 9))]))
        kit.d.ticks(5)

        when:
        kit.d.executor.stop()

        then:
        kit.guardChecks == 10
    }

    def "stopping a tree twice stops each running task once"() {
        given:
        def kit = new Kit()
        kit.d.launch(kit.fly('a', 9) >> kit.fly('b', 9) | kit.fly('c', 9))
        kit.d.ticks(2)

        when:
        kit.d.executor.stop()
        kit.d.executor.stop()

        then:
        kit.journal.lines('stop') == ['stop a 1 @0.2', 'stop c 2 @0.2']
    }

    def "a tree that never started hears nothing when stopped"() {
        given:
        def kit = new Kit()
        def t = kit.fly('a', 9) | kit.fly('b', 9)
        def allocation = new Allocation()
        t.allocate(kit.d.all(), allocation)
        def ex = t.executor
        ex.initialize(kit.d.context, allocation)

        when:
        ex.stop()

        then:
        ex.completed
        kit.journal.lines().empty
        kit.d.listener.events.empty
    }

    def "a constraint that cuts a sequence short stops the vehicle actually flying (F-15)"() {
        given:
        def kit = new Kit()
        kit.d.launch((kit.fly('survey', 0.2) >> kit.fly('photo', 9) >> kit.fly('home', 9)) / { kit.d.now() >= 0.5 - 1e-9 })

        when:
        kit.d.runToEnd()

        then:
        kit.journal.lines() == ['start survey 1 @0', 'done survey 1 @0.2', 'start photo 1 @0.2', 'stop photo 1 @0.5']
    }

    def "an interrupt of the script thread stops the running tree before run gives up"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def platform = new TestPlatform()
        platform.addNode('1')
        def env = new Environment(platform, clock, new RecordingListener())
        env.select(NodeFilter.ANY, 1, 0)
        clock.schedule(java.time.Duration.ofMillis(250), { Thread.currentThread().interrupt() } as Runnable)

        when:
        env.run(new FlyTask(platform, 'survey', 10))

        then:
        thrown(InterruptedException)
        platform.journal*.toString() == ['start survey 1 @0.0', 'stop survey 1 @0.3']

        cleanup:
        Thread.interrupted()
    }
}
