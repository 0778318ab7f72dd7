package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.core.ErrorHandler.Decision.IGNORE
import static dolphin.core.ErrorHandler.Decision.PROPAGATE

/** Reference A.2 "watch T onError { msg -> ... }" and B.6 (watcher row); the decision is taken per error. */
@Timeout(30)
class WatcherTaskSpec extends Specification {

    Driver d = new Driver()
    Journal journal = new Journal()
    List<String> handled = []

    ErrorHandler handler(ErrorHandler.Decision decision) {
        { String msg -> handled << msg; decision } as ErrorHandler
    }

    def "a task that ends DONE makes the watcher DONE without calling the handler"() {
        given:
        d.launch(new WatcherTask(Probe.lasting(journal, 'a', 0.3), handler(PROPAGATE)))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        d.time() == '0.3'
        handled.empty
    }

    def "ignore: the handler gets the error message and the watcher is DONE, carrying the message"() {
        given:
        d.launch(new WatcherTask(Probe.failing(journal, 'a', 0.2, 'camera fault'), handler(IGNORE)))

        when:
        def cs = d.runToEnd()

        then:
        cs.done
        cs.message == 'camera fault'
        d.time() == '0.2'
        handled == ['camera fault']
        d.listener.messages.any { it.contains('ignored') && it.contains('camera fault') }
    }

    def "propagate: the watcher ends in ERROR with the same message"() {
        given:
        d.launch(new WatcherTask(Probe.failing(journal, 'a', 0.2, 'camera fault'), handler(PROPAGATE)))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('camera fault')
        handled == ['camera fault']
    }

    def "the decision is taken for each error: one handler ignores one error and propagates the next"() {
        given:
        def h = { String msg -> handled << msg; msg.startsWith('minor') ? IGNORE : PROPAGATE } as ErrorHandler
        def first = new WatcherTask(Probe.failing(journal, 'a', 0.1, 'minor: gimbal'), h)
        def second = new WatcherTask(Probe.failing(journal, 'b', 0.1, 'fatal: motor'), h)
        d.launch(first >> second)

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('fatal: motor')
        handled == ['minor: gimbal', 'fatal: motor']
        journal.lines() == ['start a 1 @0', 'error a 1 @0.1', 'start b 1 @0.1', 'error b 1 @0.2']
    }

    def "a handler that ignored once may propagate the next time: nothing sticks between errors"() {
        given:
        def decisions = [IGNORE, PROPAGATE]
        def h = { String msg -> handled << msg; decisions.remove(0) } as ErrorHandler
        def w = new WatcherTask(Probe.failing(journal, 'a', 0.1, 'oops'), h)
        d.launch(w >> w)

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.error('oops')
        handled == ['oops', 'oops']
    }

    def "an ignored error lets a concurrent sibling carry on"() {
        given:
        d.launch(new WatcherTask(Probe.failing(journal, 'a', 0.1, 'oops'), handler(IGNORE)) | Probe.lasting(journal, 'b', 0.4))

        when:
        def cs = d.runToEnd()

        then:
        cs == CompletionState.DONE
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'error a 1 @0.1', 'done b 2 @0.4']
    }

    def "a propagated error stops a concurrent sibling"() {
        given:
        d.launch(new WatcherTask(Probe.failing(journal, 'a', 0.1, 'oops'), handler(PROPAGATE)) | Probe.lasting(journal, 'b', 0.4))

        when:
        def cs = d.runToEnd()

        then:
        cs.error
        journal.lines() == ['start a 1 @0', 'start b 2 @0', 'error a 1 @0.1', 'stop b 2 @0.1']
    }

    def "an exception from the handler (e.g. halt) comes out of the step"() {
        given:
        def h = { String msg -> throw new IllegalStateException("halt: ${msg}") } as ErrorHandler
        d.launch(new WatcherTask(Probe.failing(journal, 'a', 0, 'oops'), h))

        when:
        d.executor.step()

        then:
        def e = thrown(IllegalStateException)
        e.message == 'halt: oops'
    }

    def "stopping the watcher stops its task"() {
        given:
        d.launch(new WatcherTask(Probe.lasting(journal, 'a', 10), handler(IGNORE)))
        d.ticks(2)

        when:
        d.executor.stop()

        then:
        journal.lines() == ['start a 1 @0', 'stop a 1 @0.2']
        handled.empty
    }

    def "the watcher allocates what its task needs"() {
        given:
        def available = d.all()

        expect:
        new WatcherTask(Probe.lasting(journal, 'a', 1), handler(IGNORE)).allocate(available, new Allocation())
        available.toString() == '{ 2 3 }'
    }
}
