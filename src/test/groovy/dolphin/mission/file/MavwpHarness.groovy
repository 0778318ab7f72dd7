package dolphin.mission.file

import dolphin.mission.model.ItemText
import dolphin.mission.model.MissionItem
import groovy.json.JsonSlurper

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.TimeUnit

/**
 * Runs harness/mavwp_check.py (pymavlink's mavwp, from the project's venv) on .waypoints files and
 * compares what it loaded with our items. Needs the venv the build creates (harness/venv.sh);
 * without it the specs fail, they do not skip. Surefire runs in the project directory.
 */
final class MavwpHarness {

    static final Path PROJECT = Paths.get('').toAbsolutePath()
    static final Path PYTHON = PROJECT.resolve('.venv/bin/python')
    static final Path SCRIPT = PROJECT.resolve('harness/mavwp_check.py')
    static final long TIMEOUT_SECONDS = 60

    private MavwpHarness() {
    }

    /** What mavwp loaded from each file, in order: maps with file, count, units, items. */
    static List<Map> load(List<Path> files) {
        load(files, null)
    }

    /** Same, with the fence loader ({@code kind} "fence") or the rally loaders ("rally"). */
    static List<Map> load(List<Path> files, String kind) {
        if (!Files.isExecutable(PYTHON)) {
            throw new IllegalStateException("the mavwp specs need the project's Python venv with the pinned pymavlink at " +
                    "$PYTHON; the Maven build creates it (harness/generate-bindings.sh runs harness/venv.sh), or run " +
                    "'bash harness/venv.sh' in $PROJECT")
        }
        Path dir = Files.createTempDirectory('mavwp')
        try {
            Path stdout = dir.resolve('stdout'), stderr = dir.resolve('stderr')
            List<String> command = ([PYTHON, SCRIPT] + (kind ? ["--$kind"] : []) + files).collect { it.toString() }
            Process p = new ProcessBuilder(command).directory(PROJECT.toFile())
                    .redirectInput(ProcessBuilder.Redirect.from(new File('/dev/null')))
                    .redirectOutput(stdout.toFile()).redirectError(stderr.toFile()).start()
            if (!p.waitFor(TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                p.destroyForcibly()
                p.waitFor(10, TimeUnit.SECONDS)
                throw new AssertionError("mavwp_check.py did not finish within $TIMEOUT_SECONDS s: $command")
            }
            if (p.exitValue() != 0) {
                throw new AssertionError("mavwp_check.py exited with ${p.exitValue()}: ${Files.readString(stderr)}")
            }
            Files.readAllLines(stdout).findAll { it }.collect { new JsonSlurper().parseText(it) as Map }
        } finally {
            dir.toFile().deleteDir()
        }
    }

    /**
     * The differences between our items and mavwp's, empty when they agree: seq and CURRENT as we
     * wrote them, command, the file's (float) frame, params and altitude as the same float32 (NaN
     * as NaN), latitude and longitude within 1e-7 degrees and rounding to the same degE7, autocontinue.
     * mavwp turns a line-0 command 0 into NAV_WAYPOINT; our item 0 is a NAV_WAYPOINT already, so
     * commands compare as they are.
     */
    static List<String> differences(List<MissionItem> ours, Map loaded) {
        List<String> diffs = []
        List<Map> theirs = loaded.items as List<Map>
        if (loaded.count != ours.size() || theirs.size() != ours.size()) {
            return ["${ours.size()} items written, mavwp loaded ${loaded.count}".toString()]
        }
        ours.eachWithIndex { MissionItem o, int i ->
            Map t = theirs[i]
            def check = { String what, boolean same -> if (!same) { diffs << "item $i: $what: ours ${o}, mavwp ${t}".toString() } }
            check('seq', t.seq == i)
            check('current', t.current == (i == 0 ? 1 : 0))
            check('command', t.command == o.command())
            check('frame', t.frame == ItemText.fileFrame(o.frame()))
            check('param1', sameFloat(t.param1, o.param1()))
            check('param2', sameFloat(t.param2, o.param2()))
            check('param3', sameFloat(t.param3, o.param3()))
            check('param4', sameFloat(t.param4, o.param4()))
            check('z', sameFloat(t.z, o.z()))
            check('x', sameDegrees(t.x, o.x()))
            check('y', sameDegrees(t.y, o.y()))
            check('autocontinue', t.autocontinue == (o.autocontinue() ? 1 : 0))
            check('mission_type', t.mission_type == 0)
        }
        diffs
    }

    /** The same float32: NaN as "NaN", otherwise the double mavwp parsed rounds to our float (0 and -0 alike: JSON). */
    static boolean sameFloat(Object theirs, float ours) {
        if (Float.isNaN(ours)) {
            return theirs == 'NaN'
        }
        if (!(theirs instanceof Number)) {
            return false
        }
        float f = (float) ((Number) theirs).doubleValue()
        Float.floatToIntBits(f) == Float.floatToIntBits(ours) || (f == 0f && ours == 0f)
    }

    static boolean sameDegrees(Object theirs, int degE7) {
        if (!(theirs instanceof Number)) {
            return false
        }
        BigDecimal d = theirs as BigDecimal
        (d - BigDecimal.valueOf(degE7, 7)).abs() <= 1e-7 && Math.round(d.doubleValue() * 1e7) == degE7
    }
}
