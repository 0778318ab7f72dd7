package dolphin.editor

import dolphin.core.ManualClock
import java.time.Duration
import org.eclipse.lsp4j.Diagnostic
import org.eclipse.lsp4j.Position
import org.eclipse.lsp4j.PublishDiagnosticsParams
import org.eclipse.lsp4j.Range
import spock.lang.Specification

/**
 * The debounce, on a manual clock and without the scheduler's thread: the test runs the due checks
 * itself, at the clock times it chooses.
 */
class DiagnosticsSchedulerSpec extends Specification {

    static final Duration QUIET = Duration.ofMillis(250)

    ManualClock clock = new ManualClock()
    List<String> checked = []
    List<PublishDiagnosticsParams> published = []
    DiagnosticsScheduler scheduler = new DiagnosticsScheduler(clock, QUIET, { OpenDocument d ->
        checked << d.text()
        [new Diagnostic(new Range(new Position(0, 0), new Position(0, 1)), "mistake in version ${d.version()}".toString())]
    }, { published << it })

    def "a burst of changes gives one check, of the last text, once the document has been quiet for 250 ms"() {
        when: 'five changes 100 ms apart'
        (1..5).each { v ->
            scheduler.changed(new OpenDocument('file:///a.dolphin', v, "text ${v}".toString()))
            clock.advance(Duration.ofMillis(100))
        }

        then: 'during the burst nothing was due'
        checked == []

        when: '249 ms after the last change'
        clock.advance(Duration.ofMillis(149))

        then:
        scheduler.runDueChecks() == 0
        checked == []
        scheduler.hasPending()

        when: '250 ms after it'
        clock.advance(Duration.ofMillis(1))

        then: 'one check, of the last text, published with its version'
        scheduler.runDueChecks() == 1
        checked == ['text 5']
        published*.version == [5]
        published[0].diagnostics*.message*.getLeft() == ['mistake in version 5']
        !scheduler.hasPending()
        scheduler.runDueChecks() == 0
    }

    def "documents are quiet each on its own: a change to one does not hold up another"() {
        when:
        scheduler.changed(new OpenDocument('file:///a.dolphin', 1, 'a'))
        clock.advance(Duration.ofMillis(200))
        scheduler.changed(new OpenDocument('file:///b.dolphin', 1, 'b'))
        clock.advance(Duration.ofMillis(50))

        then:
        scheduler.runDueChecks() == 1
        checked == ['a']

        when:
        clock.advance(Duration.ofMillis(200))

        then:
        scheduler.runDueChecks() == 1
        checked == ['a', 'b']
    }

    def "closing a document drops its pending check and clears its diagnostics"() {
        when:
        scheduler.changed(new OpenDocument('file:///a.dolphin', 1, 'a'))
        scheduler.closed('file:///a.dolphin')
        clock.advance(QUIET)

        then:
        scheduler.runDueChecks() == 0
        checked == []
        published*.uri == ['file:///a.dolphin']
        published[0].diagnostics == []
        published[0].version == null
    }

    def "the thread checks what is due: on a clock that jumps to each wait's end, at once"() {
        given:
        def autoClock = ManualClock.autoAdvancing()
        def done = new java.util.concurrent.LinkedBlockingQueue<PublishDiagnosticsParams>()
        def threaded = new DiagnosticsScheduler(autoClock, QUIET, { OpenDocument d -> [] }, { done.add(it) })
        threaded.start()

        when:
        threaded.changed(new OpenDocument('file:///a.dolphin', 7, 'a'))
        def p = done.poll(LspTestClient.DEADLINE_SECONDS, java.util.concurrent.TimeUnit.SECONDS)

        then:
        p.version == 7
        autoClock.nanoTime() >= QUIET.toNanos()

        cleanup:
        threaded.close()
    }
}
