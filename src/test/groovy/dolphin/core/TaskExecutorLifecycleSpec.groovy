package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

import static dolphin.core.CompletionState.Type.*
import static dolphin.core.TaskExecutor.State.*

/** Reference B.1, with the fixes F-15/E-21: each executor ends exactly once, by itself or by a stop. */
@Timeout(30)
class TaskExecutorLifecycleSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()

    /** A task needing no vehicle whose executor counts its hooks; steps return the given states in turn. */
    static class Counting implements Task {
        final List<CompletionState> script
        final Map<String, Integer> calls = [:].withDefault { 0 }
        final List<TaskExecutor.State> statesInCompletion = []

        Counting(CompletionState... script) { this.script = script as List }

        String getId() { 'counting' }

        boolean allocate(NodeSet available, Allocation allocation) { true }

        TaskExecutor getExecutor() {
            Counting owner = this
            new TaskExecutor(this) {
                int n

                protected void onInitialize(Allocation a) { owner.calls.initialize++ }

                protected void onStart() { owner.calls.start++ }

                protected CompletionState onStep() {
                    owner.calls.step++
                    owner.script[Math.min(n++, owner.script.size() - 1)]
                }

                protected void onCompletion() {
                    owner.calls.completion++
                    owner.statesInCompletion << getState()
                }

                protected void onStop() { owner.calls.stop++ }
            }
        }
    }

    def "an executor goes INITIALIZING, READY, EXECUTING, COMPLETED"() {
        given:
        def t = Probe.lasting(journal, 'a', 0.2)
        def ex = t.executor

        expect:
        ex.state == INITIALIZING
        ex.completionState.type == UNDEFINED

        when:
        t.allocate(d.all(), d.allocation)
        ex.initialize(d.context, d.allocation)

        then:
        ex.state == READY
        journal.lines('init', 'start') == ['init a 1 @0']

        when:
        ex.start()

        then:
        ex.state == EXECUTING
        journal.lines('start') == ['start a 1 @0']

        when:
        def seen = (1..3).collect {
            def cs = ex.step()
            d.clock.advance(Environment.TICK)
            [cs.type, ex.state]
        }

        then:
        seen == [[IN_PROGRESS, EXECUTING], [IN_PROGRESS, EXECUTING], [DONE, COMPLETED]]
        ex.completionState == CompletionState.DONE
        ex.completed
        !ex.wasStopped()
        journal.lines() == ['start a 1 @0', 'done a 1 @0.2']
    }

    @Unroll
    def "#call in the wrong state throws an EnvironmentException naming the expected state (#situation)"() {
        given:
        def t = new Counting(CompletionState.DONE)
        def ex = t.executor
        prepare.call(ex, d.context)

        when:
        action.call(ex, d.context)

        then:
        def e = thrown(EnvironmentException)
        e.message.contains("expected ${expected} state")

        where:
        call         | situation              | prepare                                                        | action                     | expected
        'start'      | 'not initialised'      | { p, c -> }                                                    | { q, k -> q.start() }      | 'READY'
        'step'       | 'not initialised'      | { p, c -> }                                                    | { q, k -> q.step() }       | 'EXECUTING'
        'step'       | 'not started'          | { p, c -> p.initialize(c, new Allocation()) }                  | { q, k -> q.step() }       | 'EXECUTING'
        'initialize' | 'already initialised'  | { p, c -> p.initialize(c, new Allocation()) }                  | { q, k -> q.initialize(k, new Allocation()) } | 'INITIALIZING'
        'start'      | 'already started'      | { p, c -> p.initialize(c, new Allocation()); p.start() }       | { q, k -> q.start() }      | 'READY'
        'step'       | 'completed'            | { p, c -> p.initialize(c, new Allocation()); p.start(); p.step() } | { q, k -> q.step() }   | 'EXECUTING'
        'step'       | 'stopped'              | { p, c -> p.initialize(c, new Allocation()); p.start(); p.stop() } | { q, k -> q.step() }   | 'EXECUTING'
        'start'      | 'stopped before start' | { p, c -> p.initialize(c, new Allocation()); p.stop() }        | { q, k -> q.start() }      | 'READY'
    }

    def "an IN_PROGRESS step keeps the executor running; a DONE step completes it and calls onCompletion once, after the state is COMPLETED"() {
        given:
        def t = new Counting(CompletionState.IN_PROGRESS, CompletionState.IN_PROGRESS, CompletionState.done('landed'))
        def ex = d.launch(t)

        when:
        def states = d.ticks(3)

        then:
        states == [IN_PROGRESS, IN_PROGRESS, DONE]
        ex.completionState == CompletionState.done('landed')
        t.calls == [initialize: 1, start: 1, step: 3, completion: 1]
        t.statesInCompletion == [COMPLETED]
    }

    def "an ERROR step completes the executor with the error and its message"() {
        given:
        def t = new Counting(CompletionState.IN_PROGRESS, CompletionState.error('motor failure'))
        def ex = d.launch(t)

        when:
        def states = d.ticks(2)

        then:
        states == [IN_PROGRESS, ERROR]
        ex.state == COMPLETED
        ex.completionState.error
        ex.completionState.message == 'motor failure'
        t.calls.completion == 1
        t.calls.stop == 0
    }

    def "stopping a running executor calls onStop exactly once, never onCompletion; a second stop does nothing"() {
        given:
        def t = new Counting(CompletionState.IN_PROGRESS)
        def ex = d.launch(t)
        d.ticks(2)

        when:
        ex.stop()

        then:
        ex.state == COMPLETED
        ex.wasStopped()
        ex.completionState.type == UNDEFINED
        t.calls.stop == 1
        t.calls.completion == 0
        d.listener.events*.kind == [TaskEvent.Kind.STARTED, TaskEvent.Kind.STOPPED]

        when:
        ex.stop()

        then:
        t.calls.stop == 1
        t.calls.completion == 0
        d.listener.events*.kind == [TaskEvent.Kind.STARTED, TaskEvent.Kind.STOPPED]
    }

    def "stopping an executor that never started only marks it COMPLETED: no onStop, no onCompletion, no event"() {
        given:
        def t = new Counting(CompletionState.DONE)
        def ex = t.executor
        ex.initialize(d.context, new Allocation())

        when:
        ex.stop()
        ex.stop()

        then:
        ex.state == COMPLETED
        ex.wasStopped()
        ex.completionState.type == UNDEFINED
        t.calls == [initialize: 1]
        d.listener.events.empty
    }

    def "a stop after the executor completed by itself is ignored"() {
        given:
        def t = new Counting(CompletionState.DONE)
        def ex = d.launch(t)
        d.tick()

        when:
        ex.stop()

        then:
        !ex.wasStopped()
        ex.completionState == CompletionState.DONE
        t.calls.completion == 1
        t.calls.stop == 0
        d.listener.events*.kind == [TaskEvent.Kind.STARTED, TaskEvent.Kind.COMPLETED]
    }

    def "STARTED and COMPLETED events reach the listener with the task, its vehicles, the final state and the clock time"() {
        given:
        def a = Probe.lasting(journal, 'a', 0.3)
        d.clock.advance(java.time.Duration.ofSeconds(2))

        when:
        d.launch(a, d.set('2'))
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        d.listener.events.size() == 2
        with(d.listener.events[0]) {
            kind == TaskEvent.Kind.STARTED
            task.is(a)
            vehicles == ['2']
            time == 2.0d
            platformTask
        }
        with(d.listener.events[1]) {
            kind == TaskEvent.Kind.COMPLETED
            task.is(a)
            vehicles == ['2']
            state == CompletionState.DONE
            Math.abs(time - 2.3d) < 1e-9
        }
    }

    def "a STOPPED event reaches the listener when a running task is cut short"() {
        given:
        def a = Probe.endless(journal, 'a')
        d.launch(a)
        d.ticks(4)

        when:
        d.executor.stop()

        then:
        d.listener.events*.kind == [TaskEvent.Kind.STARTED, TaskEvent.Kind.STOPPED]
        d.listener.events[1].task.is(a)
        Math.abs(d.listener.events[1].time - 0.4d) < 1e-9
        journal.lines() == ['start a 1 @0', 'stop a 1 @0.4']
    }

    def "composite executors report their own events too"() {
        given:
        def a = Probe.lasting(journal, 'a', 0.1)
        def b = Probe.lasting(journal, 'b', 0.1)
        def seq = a >> b

        when:
        d.launch(seq)
        d.runToEnd()

        then:
        d.listener.events.findAll { it.task.is(seq) }*.kind == [TaskEvent.Kind.STARTED, TaskEvent.Kind.COMPLETED]
        d.listener.events.findAll { it.task.is(a) }*.kind == [TaskEvent.Kind.STARTED, TaskEvent.Kind.COMPLETED]
        d.listener.events.findAll { it.task.is(b) }*.kind == [TaskEvent.Kind.STARTED, TaskEvent.Kind.COMPLETED]
        !d.listener.events.find { it.task.is(seq) }.platformTask
    }

    def "timeElapsed is the clock time since start"() {
        given:
        def ex = d.launch(new Counting(CompletionState.IN_PROGRESS))

        when:
        d.clock.advance(java.time.Duration.ofMillis(1250))

        then:
        Math.abs(ex.timeElapsed() - 1.25d) < 1e-9
    }

    def "a platform task whose vehicle is not connected ends in ERROR naming the vehicle, without stepping the task"() {
        given:
        def a = Probe.endless(journal, 'a')
        def ex = d.launch(a, d.set('2'))
        d.ticks(3)

        when:
        d.node('2').connected = false
        def cs = ex.step()

        then:
        cs.error
        cs.message.startsWith('vehicle 2 lost')
        ex.state == COMPLETED
        journal.stepTimes('a') == ['0', '0.1', '0.2']
        journal.lines() == ['start a 2 @0', 'error a 2 @0.3']
        d.listener.events.last().kind == TaskEvent.Kind.COMPLETED
        d.listener.events.last().state.error
    }
}
