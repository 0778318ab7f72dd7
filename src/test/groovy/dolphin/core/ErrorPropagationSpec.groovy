package dolphin.core

import dolphin.testing.FlyTask
import dolphin.testing.TestPlatform
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

/**
 * Reference B.6: how a task-level ERROR travels upward, row by row, and what the root does with it
 * (F-13: reported, not thrown). The failing task 'f' fails at 0.2 s with 'boom'.
 */
@Timeout(30)
class ErrorPropagationSpec extends Specification {

    static class Kit {
        final Driver d = new Driver()
        final Journal journal = new Journal()
        final Probe f = Probe.failing(journal, 'f', 0.2, 'boom')
        final Probe a = Probe.lasting(journal, 'a', 1)
        final Probe b = Probe.lasting(journal, 'b', 1)
        final Probe quick = Probe.lasting(journal, 'quick', 0.1)

        TaskGuard always(Task t) { new TaskGuard({ true } as Condition, t) }

        Task watch(Task t, ErrorHandler.Decision decision) { new WatcherTask(t, { decision } as ErrorHandler) }
    }

    @Unroll
    def "#row: #tree ends #expected"() {
        given:
        def kit = new Kit()
        Task task = build.call(kit)
        kit.d.launch(task)

        when:
        def cs = kit.d.runToEnd()

        then:
        cs == expected
        kit.journal.lines() == lines

        where:
        row                    | tree                    | build                                                                   || expected                        | lines
        'sequence, first part' | 'f >> a'                | { Kit k -> return k.f >> k.a }                                          || CompletionState.error('boom') | ['start f 1 @0', 'error f 1 @0.2']
        'sequence, second part'| 'quick >> f'            | { Kit k -> return k.quick >> k.f }                                      || CompletionState.error('boom') | ['start quick 1 @0', 'done quick 1 @0.1', 'start f 1 @0.1', 'error f 1 @0.3']
        'concurrent, first'    | 'f | a'                 | { Kit k -> k.f | k.a }                                                  || CompletionState.error('boom') | ['start f 1 @0', 'start a 2 @0', 'error f 1 @0.2', 'stop a 2 @0.2']
        'concurrent, second'   | 'a | f'                 | { Kit k -> k.a | k.f }                                                  || CompletionState.error('boom') | ['start a 1 @0', 'start f 2 @0', 'error f 2 @0.2', 'stop a 1 @0.2']
        'allOf, at once'       | 'allOf(f, a)'           | { Kit k -> new AllOfTask([k.always(k.f), k.always(k.a)]) }              || CompletionState.error('boom') | ['start f 1 @0', 'error f 1 @0.2']
        'oneOf, passed through'| 'oneOf(f, a)'           | { Kit k -> new ChoiceTask([k.always(k.f), k.always(k.a)]) }             || CompletionState.error('boom') | ['start f 1 @0', 'error f 1 @0.2']
        'waitFor, passed through' | 'waitFor then f'     | { Kit k -> new ChoiceTask([k.always(k.f)]) }                            || CompletionState.error('boom') | ['start f 1 @0', 'error f 1 @0.2']
        'constrained'          | 'f / { false }'         | { Kit k -> k.f / ({ false } as Condition) }                             || CompletionState.error('boom') | ['start f 1 @0', 'error f 1 @0.2']
        'during'               | 'during 5 run f'        | { Kit k -> new TimeConstrainedTask(k.f, 5) }                            || CompletionState.error('boom') | ['start f 1 @0', 'error f 1 @0.2']
        'watcher, ignore'      | 'watch f: ignore'       | { Kit k -> k.watch(k.f, ErrorHandler.Decision.IGNORE) }                 || CompletionState.done('boom')  | ['start f 1 @0', 'error f 1 @0.2']
        'watcher, propagate'   | 'watch f: propagate'    | { Kit k -> k.watch(k.f, ErrorHandler.Decision.PROPAGATE) }              || CompletionState.error('boom') | ['start f 1 @0', 'error f 1 @0.2']
        'nested'               | '(quick >> f) | a'      | { Kit k -> return (k.quick >> k.f) | k.a }                              || CompletionState.error('boom') | ['start quick 1 @0', 'start a 2 @0', 'done quick 1 @0.1', 'start f 1 @0.1', 'error f 1 @0.3', 'stop a 2 @0.3']
        'nested, ignored'      | '(watch f: ignore) >> quick' | { Kit k -> return k.watch(k.f, ErrorHandler.Decision.IGNORE) >> k.quick } || CompletionState.DONE | ['start f 1 @0', 'error f 1 @0.2', 'start quick 1 @0.2', 'done quick 1 @0.3']
        'deep'                 | '((a | f) / { false }) >> b' | { Kit k -> return (k.a | k.f) / ({ false } as Condition) >> k.b } || CompletionState.error('boom') | ['start a 1 @0', 'start f 2 @0', 'error f 2 @0.2', 'stop a 1 @0.2']
    }

    def "a root ERROR is returned and reported to the listener, not thrown (F-13)"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def platform = new TestPlatform()
        platform.addNode('1')
        def listener = new RecordingListener()
        def env = new Environment(platform, clock, listener)
        env.select(NodeFilter.ANY, 1, 0)

        when:
        def cs = env.run(new FlyTask(platform, 'survey', 10, 0.5d, 'motor failure'))

        then:
        cs == CompletionState.error('motor failure')
        listener.messages.contains('task survey ended in ERROR: motor failure')
        Math.abs(clock.seconds() - 0.5d) < 1e-9
    }

    def "a root that ends DONE reports no error"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def platform = new TestPlatform()
        platform.addNode('1')
        def listener = new RecordingListener()
        def env = new Environment(platform, clock, listener)
        env.select(NodeFilter.ANY, 1, 0)

        when:
        def cs = env.run(new FlyTask(platform, 'survey', 1))

        then:
        cs == CompletionState.DONE
        !listener.messages.any { it.contains('ERROR') }
    }

    def "an exception thrown inside the tree comes out of run, after the running tasks were stopped"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def platform = new TestPlatform()
        platform.addNode('1')
        def env = new Environment(platform, clock, new RecordingListener())
        env.select(NodeFilter.ANY, 1, 0)
        def crash = new IdleTask(0.5) >> new ActionTask({ throw new IllegalStateException('script bug') } as Runnable)

        when:
        env.run(new FlyTask(platform, 'survey', 10) | crash)

        then:
        def e = thrown(IllegalStateException)
        e.message == 'script bug'
        platform.journal*.toString() == ['start survey 1 @0.0', 'stop survey 1 @0.5']
    }
}
