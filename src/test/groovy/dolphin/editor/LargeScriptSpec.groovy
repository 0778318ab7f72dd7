package dolphin.editor

import dolphin.core.SystemClock
import java.time.Duration
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout

/**
 * A 10,000-line script gets its diagnostics as the user types: measured in real time (the time from
 * didChange to publishDiagnostics, the 250 ms quiet period included), as a ratio against a 100-line
 * script in the same run, and printed; the test fails only past a generous deadline.
 */
@Timeout(180)
class LargeScriptSpec extends Specification {

    static final String MISSION = '''survey%d = mission {
    name "Survey %d"
    home homePos
    takeOff location(40.444233, -7.375234, 920)
    goPos 40.45, -7.37, 920
    returnHomeAndLand()
}
'''
    static final int RUNS = 3

    @AutoCleanup
    LspTestClient client = new LspTestClient(SystemClock.REAL, DolphinLanguageServer.QUIET_PERIOD)

    /** A correct script of this many lines: a home, seven-line missions, comment lines to make up the count. */
    static String script(int lines) {
        StringBuilder s = new StringBuilder('homePos = location(40.444233, -7.375234, 820)\n')
        int written = 1
        for (int n = 0; written + 7 <= lines; n++) {
            s << String.format(MISSION, n, n)
            written += 7
        }
        s << '// more to come\n' * (lines - written)
        s.toString()
    }

    /** The median time, in ms, from each change to its diagnostics; the diagnostics of the last. */
    List measure(String uri, String text, String edited, long deadlineSeconds) {
        client.open(uri, text)
        client.diagnostics(uri, 1, 60)
        List<Double> times = []
        def last = null
        (1..RUNS).each { run ->
            long start = System.nanoTime()
            client.change(uri, run + 1, edited.replace('// more to come', "// edit ${run}"))
            last = client.diagnostics(uri, run + 1, deadlineSeconds)
            times << (System.nanoTime() - start) / 1e6
        }
        client.closeDocument(uri)
        [times.sort()[RUNS.intdiv(2)], last]
    }

    def "a 10,000-line script gets its diagnostics within 10 s of a change; the time is printed against a 100-line one's"() {
        given:
        String small = script(100)
        String large = script(10_000)
        String largeBroken = large + 'x = (1 +\n'

        when:
        def (double smallMs, smallResult) = measure('file:///work/small.dolphin', small, small, 10)
        def (double largeMs, largeResult) = measure('file:///work/large.dolphin', large, large, 10)
        def (double brokenMs, brokenResult) = measure('file:///work/large-broken.dolphin', large, largeBroken, 60)
        long quiet = DolphinLanguageServer.QUIET_PERIOD.toMillis()
        println String.format('dolphin lsp, didChange to publishDiagnostics (median of %d, the %d ms quiet period included): '
                + '100 lines %.0f ms, 10,000 lines %.0f ms: %.1f times (%.1f times without the quiet period); '
                + '10,000 lines and a syntax error at the end %.0f ms', RUNS, quiet, smallMs, largeMs, largeMs / smallMs,
                (largeMs - quiet) / (smallMs - quiet), brokenMs)

        then: 'the correct scripts have none; the broken one its syntax error, on its last line'
        small.count('\n') == 100
        large.count('\n') == 10_000
        smallResult.diagnostics == []
        largeResult.diagnostics == []
        brokenResult.diagnostics.size() == 1
        brokenResult.diagnostics[0].range.start.line == 10_000
    }
}
