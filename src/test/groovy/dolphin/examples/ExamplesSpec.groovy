package dolphin.examples

import dolphin.cli.Main
import dolphin.core.Position
import dolphin.testing.ScriptLines
import java.util.concurrent.TimeUnit
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

/**
 * Every script in dsl-examples/ runs to completion against the in-process simulated fleet, as
 * `dolphin run SCRIPT --sim N --speedup X` with the command line of its row in README.md's table of
 * examples (the same as its own comment's), and its outcome is checked from the printed lines: the
 * MissionExecutor's progress ("mission X on vehicle N: ...") and the script's own messages.
 */
class ExamplesSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final String DIR = 'dsl-examples'

    /** Examples this spec runs; the first feature checks that it is every file in dsl-examples/. */
    static final List<String> COVERED = [
            'two-drones-survey', 'listing2-single-vehicle', 'listing3-two-vehicles', 'listing4-keep-two-airborne',
            'operators', 'loiters', 'survey', 'camera', 'watch-onerror', 'first-flight', 'battery-and-position', 'fleet',
            'fence', 'from-file', 'fire-watch', 'listing1-uuv-surveys', 'mapping', 'vtol-mapping']

    @Shared
    Map<String, String> commandLines = [:]

    /** The `./dolphin run ...` line of an example's own comment, or null. */
    static String commentCommand(String example) {
        def m = new File(DIR, "${example}.dolphin").text =~ /(?m)^\/\/\s+(\.\/dolphin run \S+(?: --\S+ \S+)*)\s*$/
        m.find() ? m.group(1) : null
    }

    /** README.md's table of examples: each row's file name and its "Run with" command, in order. */
    static List<List<String>> readmeRows() {
        String readme = new File('README.md').text
        int table = readme.indexOf('| Example | Shows | Run with |')
        assert table >= 0: 'README.md has no table of examples'
        readme.substring(table).readLines().drop(2).takeWhile { it.startsWith('|') }.collect { row ->
            def m = row =~ /^\| `([^`]+)\.dolphin` \|.*\| `(\.\/dolphin run [^`]+)` \|$/
            assert m.find(): "README.md: a row of the examples' table without a file and a './dolphin run' command: ${row}"
            [m.group(1), m.group(2)]
        }
    }

    /** Runs the example with the command of its README row and {@code more} arguments; a deadline of 90 s. */
    Map run(String example, List<String> more = []) {
        File file = new File(DIR, "${example}.dolphin")
        String command = readmeRows().find { it[0] == example }?.getAt(1)
        assert command: "README.md: no row for ${file} in the table of examples"
        List<String> words = command.split(/\s+/).toList()
        assert words.take(3) == ['./dolphin', 'run', file.path]
        List<String> args = words.drop(1) + more
        assert args.contains('--sim')
        def out = new StringWriter()
        def err = new StringWriter()
        def code = new java.util.concurrent.CompletableFuture<Integer>()
        def thread = Thread.start("example ${example}") {
            try {
                code.complete(Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(args as String[]))
            } catch (Throwable t) {
                code.completeExceptionally(t)
            }
        }
        Integer exit
        try {
            exit = code.get(90, TimeUnit.SECONDS)
        } catch (java.util.concurrent.TimeoutException e) {
            thread.interrupt()
            assert false: "${example} did not end within 90 s; output so far:\n${out}\n${err}"
        }
        List<String> lines = out.toString().readLines().collect { it.replaceFirst(/^\[\s*[\d.]+ s\] /, '') }
        [code: exit, out: out.toString(), err: err.toString(), lines: lines]
    }

    def "every file in dsl-examples/ is run by this spec"() {
        expect:
        new File(DIR).listFiles().findAll { it.name.endsWith('.dolphin') }*.name*.replace('.dolphin', '').sort() == COVERED.sort()
    }

    def "every example has one row in README.md's table, whose command is the one in the example's own comment"() {
        given:
        List<List<String>> rows = readmeRows()

        expect:
        rows*.getAt(0).sort() == COVERED.sort()
        rows.every { String example, String command -> command == commentCommand(example) }
    }

    @Timeout(100)
    def "the recorded two-vehicle scenario: take off, survey, cut at 70 %, return mission, land and disarm at home, exit 0"() {
        when:
        def r = run('two-drones-survey')
        List<String> lines = r.lines

        then:
        r.code == 0
        [[1, 'Survey Area 1', 'Return to base 1', 1], [2, 'Survey Area 2', 'Return to base 2', -1]].every { n, survey, back, northward ->
            int i = ScriptLines.after(lines, -1, "mission ${survey} on vehicle ${n}: uploading 45 items")
            i = ScriptLines.after(lines, i, "mission ${survey} on vehicle ${n}: armed")
            i = ScriptLines.after(lines, i, "mission ${survey} on vehicle ${n}: started")
            i = ScriptLines.after(lines, i, "mission ${survey} on vehicle ${n}: item 1 of 44 reached")   // the take-off
            i = ScriptLines.after(lines, i, "mission ${survey} on vehicle ${n}: cut short: RTL")
            // cut at the threshold, on its own survey leg (north for vehicle 1, south for 2), at 920 m
            int cut = lines.findIndexOf(i) { it.startsWith("vehicle { ${n} } cut short at battery ") }
            assert cut > i
            assert (lines[cut] =~ /battery (\d+) %/)[0][1].toInteger() in 60..69
            Position p = ScriptLines.parsePosition(lines[cut])
            assert (p.latitudeDegrees() - HOME.latitudeDegrees()) * northward * 111_000 > 500
            assert Math.abs(p.hae() - 920) < 5
            i = ScriptLines.after(lines, cut, "mission ${back} on vehicle ${n}: uploading 2 items")
            i = ScriptLines.after(lines, i, "mission ${back} on vehicle ${n}: started")
            i = ScriptLines.after(lines, i, "mission ${back} on vehicle ${n}: done")   // landed and disarmed
            assert !lines.any { it.contains("mission ${survey} on vehicle ${n}: done") }
            int landed = lines.findIndexOf(i) { it.startsWith("vehicle { ${n} } landed at ") }
            assert landed > i
            assert ScriptLines.parsePosition(lines[landed]).distanceTo(HOME) < 5
            true
        }
        lines.contains('both vehicles back: DONE')
        lines.last() == 'dsl-examples/two-drones-survey.dolphin: completed'
        !r.out.contains('ERROR')
    }

    @Timeout(100)
    def "Listing 2: one vehicle flies until 30 %, is sent home, flies the return mission and lands"() {
        when:
        def r = run('listing2-single-vehicle')

        then:
        r.code == 0
        ScriptLines.inOrder(r.lines, 'mission Survey Area on vehicle 1: started', 'mission Survey Area on vehicle 1: cut short: RTL',
                'mission Return to base on vehicle 1: started', 'mission Return to base on vehicle 1: done')
        r.lines.find { it.startsWith('vehicle { 1 } is back home: battery ') }
        r.lines.last() == 'dsl-examples/listing2-single-vehicle.dolphin: completed'
    }

    @Timeout(100)
    def "Listing 3: two vehicles survey concurrently, each is cut at 30 % and flies the one return mission on itself"() {
        when:
        def r = run('listing3-two-vehicles')

        then:
        r.code == 0
        [[1, 'Survey Area 1'], [2, 'Survey Area 2']].every { n, survey ->
            int i = ScriptLines.after(r.lines, -1, "mission ${survey} on vehicle ${n}: started")
            i = ScriptLines.after(r.lines, i, "mission ${survey} on vehicle ${n}: cut short: RTL")
            i = ScriptLines.after(r.lines, i, "mission Return to base on vehicle ${n}: started")
            ScriptLines.after(r.lines, i, "mission Return to base on vehicle ${n}: done") > 0
        }
        r.lines.contains('vehicles { 1 } and { 2 } are back home')
        r.lines.last() == 'dsl-examples/listing3-two-vehicles.dolphin: completed'
    }

    @Timeout(100)
    def "Listing 4: two rounds keep two vehicles flying and swap in fresh ones: four distinct vehicles flown"() {
        when:
        def r = run('listing4-keep-two-airborne')
        def flown = r.lines.findAll { it ==~ /mission Survey Area \d on vehicle \d+: started/ }
                .collect { (it =~ /vehicle (\d+)/)[0][1].toInteger() }

        then:
        r.code == 0
        flown.sort() == [1, 2, 3, 4]
        (1..4).every { n ->
            int i = ScriptLines.after(r.lines, -1, "mission Return to base on vehicle ${n}: started")
            ScriptLines.after(r.lines, i, "mission Return to base on vehicle ${n}: done") > 0
        }
        int round1 = ScriptLines.after(r.lines, -1, 'round done: vehicles { 1 } and { 2 } are back home')
        // the fresh vehicles are picked while 1 and 2 are still bound, and fly after them
        ScriptLines.after(r.lines, round1, 'picked { 3 } from the free vehicles { 3 4 }') > round1
        ScriptLines.after(r.lines, round1, 'mission Survey Area 1 on vehicle 3: started') > round1
        ScriptLines.after(r.lines, round1, 'round done: vehicles { 3 } and { 4 } are back home') > round1
        r.lines.last() == 'dsl-examples/listing4-keep-two-airborne.dolphin: completed'
    }

    @Timeout(100)
    def "operators: sequence, concurrency, a condition, during and explicit vehicles in one execute"() {
        when:
        def r = run('operators')

        then:
        r.code == 0
        ScriptLines.inOrder(r.lines, 'mission hop on vehicle 1: done', 'task hover north started on vehicle 1',
                'mission hover north on vehicle 1: cut short: RTL', 'mission back on vehicle 1: done')
        ScriptLines.inOrder(r.lines, 'mission hover on vehicle 2: cut short: RTL', 'mission back on vehicle 2: done')
        r.lines.find { it ==~ /operators: DONE; battery \d+ % and \d+ %/ }
    }

    @Timeout(100)
    def "#example: #expected"() {
        when:
        def r = run(example)

        then:
        r.code == 0
        ScriptLines.inOrder(r.lines, *expected)
        r.lines.last() == "dsl-examples/${example}.dolphin: completed".toString()

        where:
        example                | expected
        'loiters'              | ['mission loiters on vehicle 1: item 4 of 5 reached', 'mission loiters on vehicle 1: done', 'loiters: DONE']
        'camera'               | ['mission photos on vehicle 1: uploading 11 items', 'mission photos on vehicle 1: done', 'camera: DONE']
        'mapping'              | ['mission mapping on vehicle 1: uploading 40 items', 'mission mapping on vehicle 1: item 24 of 39 reached',
                                  'mission mapping on vehicle 1: done', 'mapping: DONE']
        'vtol-mapping'         | ['mission vtol mapping on vehicle 1: item 39 added: NAV_WAYPOINT, the approach to the landing after it',
                                  'mission vtol mapping on vehicle 1: item 40 added: NAV_WAYPOINT, the approach to the landing after it',
                                  'mission vtol mapping on vehicle 1: armed', 'mission vtol mapping on vehicle 1: item 40 of 41 reached',
                                  "mission vtol mapping on vehicle 1: QLOITER, which ends ArduPlane's landing sequence",
                                  'mission vtol mapping on vehicle 1: done', 'mapping: DONE']
        'survey'               | ['mission survey on vehicle 1: cut short: RTL', 'mission return home on vehicle 1: done']
        'first-flight'         | ['mission first flight on vehicle 1: done', 'the flight ended DONE, battery *']
        'from-file'            | ['read 5 mission items, a fence of 1 region (inclusion polygon of 4 vertices), return point,'
                                          + ' 1 rally point from dsl-examples/square.plan',
                                  'mission square on vehicle 1: fence verified*', 'mission square on vehicle 1: rally points verified*',
                                  'mission square on vehicle 1: done', 'the square from the file: DONE, fence breached: false']
        'battery-and-position' | ['vehicle { 1 }: battery 100 %, position (40.444233°, -7.375234°, 820.000)',
                                  'vehicle { 2 }: battery 100 %, position (40.444233°, -7.375116°, 820.000)']
    }

    @Timeout(100)
    def "on PX4 (--sim-autopilot px4): #example"() {
        when:
        def r = run(example, ['--sim-autopilot', 'px4'])

        then:
        r.code == 0
        expected.every { List<String> lines -> ScriptLines.inOrder(r.lines, *lines) }
        r.lines.last() == "dsl-examples/${example}.dolphin: completed".toString()

        where: 'each list of lines in its order; not loiters (PX4 flies no LOITER_TURNS) nor the subs of Listing 1'
        example                      | expected
        'two-drones-survey'          | [['mission Survey Area 1 on vehicle 1: cut short: AUTO.RTL', 'mission Return to base 1 on vehicle 1: done',
                                         'both vehicles back: DONE'],
                                        ['mission Survey Area 2 on vehicle 2: cut short: AUTO.RTL', 'mission Return to base 2 on vehicle 2: done',
                                         'both vehicles back: DONE']]
        'listing2-single-vehicle'    | [['mission Survey Area on vehicle 1: cut short: AUTO.RTL', 'mission Return to base on vehicle 1: done']]
        'listing3-two-vehicles'      | [['mission Survey Area 1 on vehicle 1: cut short: AUTO.RTL', 'mission Return to base on vehicle 1: done',
                                         'vehicles { 1 } and { 2 } are back home'],
                                        ['mission Survey Area 2 on vehicle 2: cut short: AUTO.RTL', 'mission Return to base on vehicle 2: done',
                                         'vehicles { 1 } and { 2 } are back home']]
        'listing4-keep-two-airborne' | [['round done: vehicles { 1 } and { 2 } are back home', 'mission Survey Area 1 on vehicle 3: started',
                                         'round done: vehicles { 3 } and { 4 } are back home']]
        'operators'                  | [['mission hop on vehicle 1: done', 'mission hover north on vehicle 1: cut short: AUTO.RTL',
                                         'mission back on vehicle 1: done', 'operators: DONE*'],
                                        ['mission hover on vehicle 2: cut short: AUTO.RTL', 'mission back on vehicle 2: done', 'operators: DONE*']]
        'survey'                     | [['mission survey on vehicle 1: cut short: AUTO.RTL', 'mission return home on vehicle 1: done']]
        'camera'                     | [['mission photos on vehicle 1: uploading 11 items', 'mission photos on vehicle 1: done', 'camera: DONE']]
        'watch-onerror'              | [['the fine survey failed: *', 'mission coarse survey on vehicle 1: done', 'watch: DONE']]
        'first-flight'               | [['mission first flight on vehicle 1: done', 'the flight ended DONE, battery *']]
        'battery-and-position'       | [['vehicle { 1 }: battery 100 %, position (40.444233°, -7.375234°, 820.000)']]
        'fence'                      | [['mission fenced flight on vehicle 1: fence verified*', 'mission fenced flight on vehicle 1: rally points verified*',
                                         // PX4 refuses before the flight a mission that leaves its fence (its SITL, docs/px4.md)
                                         "the mission stopped: mission fenced flight on vehicle 1: vehicle 1 found the mission infeasible: "
                                                 + "'Geofence violation for waypoint 3'",
                                         'back home: the fence did its job']]
        'from-file'                  | [['mission square on vehicle 1: fence verified*', 'mission square on vehicle 1: rally points verified*',
                                         'mission square on vehicle 1: done', 'the square from the file: DONE, fence breached: false']]
        'mapping'                    | [['mission mapping on vehicle 1: uploading 40 items', 'mission mapping on vehicle 1: done', 'mapping: DONE']]
        'vtol-mapping'               | [['mission vtol mapping on vehicle 1: armed', 'mission vtol mapping on vehicle 1: done', 'mapping: DONE']]
        'fire-watch'                 | [['mission survey west on vehicle 1: cut short: AUTO.RTL', 'mission watch the fire on vehicle 3: done'],
                                        ['mission back home on vehicle 1: done'], ['mission back home on vehicle 2: done']]
        'fleet'                      | [['picked 300 vehicles', 'all 300 patrols cut short at 90 %: DONE', 'all 300 vehicles landed']]
    }

    @Timeout(100)
    def "fire watch: a scout reads the plume, the camera vehicle is picked and sent over it, within the plume's radius"() {
        given: 'the plume of the command line: 60 m around this centre'
        Position centre = Position.fromDegrees(40.4461, -7.3752, 870)

        when:
        def r = run('fire-watch')
        String smoke = r.lines.find { it ==~ /smoke [\d.]+ read by vehicle \{ [12] \} at .*/ }
        String over = r.lines.find { it.startsWith('vehicle { 3 } over the fire at ') }

        then:
        r.code == 0
        smoke && over
        (smoke =~ /smoke ([\d.]+)/)[0][1].toDouble() > 20
        horizontal(ScriptLines.parsePosition(smoke), centre) < 60
        horizontal(ScriptLines.parsePosition(over), centre) < 60
        ScriptLines.inOrder(r.lines, 'mission survey west on vehicle 1: cut short: RTL', 'picked { 3 } from the free vehicles { 3 }',
                'mission watch the fire on vehicle 3: started', 'mission watch the fire on vehicle 3: done')
        ScriptLines.inOrder(r.lines, 'mission back home on vehicle 1: done')
        ScriptLines.inOrder(r.lines, 'mission back home on vehicle 2: done')
        r.lines.last() == 'dsl-examples/fire-watch.dolphin: completed'
    }

    static double horizontal(Position a, Position b) {
        a.distanceTo(Position.fromDegrees(b.latitudeDegrees(), b.longitudeDegrees(), a.hae()))
    }

    @Timeout(100)
    def "Listing 1: three subs with a side-scan sonar picked in the Comporta area, one survey each at 10 m, back at the surface: Done!"() {
        when:
        def r = run('listing1-uuv-surveys')

        then:
        r.code == 0
        r.lines.any { it.startsWith('picked { 1 2 3 } from the free vehicles') }
        ['survey1': 1, 'survey2': 2, 'survey3': 3].every { survey, n ->
            ScriptLines.inOrder(r.lines, "mission ${survey} on vehicle ${n}: uploading 10 items".toString(),
                    "mission ${survey} on vehicle ${n}: upload verified*".toString(), "mission ${survey} on vehicle ${n}: armed".toString(),
                    "mission ${survey} on vehicle ${n}: item 9 of 9 reached".toString(), "mission ${survey} on vehicle ${n}: done".toString())
        }
        r.lines.contains('Done!')
        r.lines.last() == 'dsl-examples/listing1-uuv-surveys.dolphin: completed'
    }

    @Timeout(100)
    def "watch/onError: the refused upload reaches the handler, which ignores it, and the next survey flies"() {
        when:
        def r = run('watch-onerror')

        then:
        r.code == 0
        r.lines.findIndexOf { it.startsWith('the fine survey failed: ') && it.contains('MAV_MISSION_NO_SPACE') } >
                r.lines.indexOf('mission fine survey on vehicle 1: uploading 1005 items')
        r.lines.indexOf('mission coarse survey on vehicle 1: done') >
                r.lines.findIndexOf { it.startsWith('the fine survey failed: ') }
        r.lines.contains('watch: DONE')
        !r.lines.any { it.contains('mission fine survey on vehicle 1: started') }
    }

    @Timeout(100)
    def "fence: the fence and rally point go up and are verified first; leaving the square is a breach, the copter returns, the handler sees it"() {
        when:
        def r = run('fence')

        then:
        r.code == 0
        ScriptLines.inOrder(r.lines, 'mission fenced flight on vehicle 1: uploading the fence: 6 items',
                'mission fenced flight on vehicle 1: fence verified*',
                'mission fenced flight on vehicle 1: uploading the rally points: 1 item',
                'mission fenced flight on vehicle 1: rally points verified*',
                'mission fenced flight on vehicle 1: uploading 5 items', 'mission fenced flight on vehicle 1: item 2 of 4 reached',
                'the mission stopped: mission fenced flight on vehicle 1: vehicle 1 breached its fence during item 3 of 4 (NAV_WAYPOINT) and left AUTO for RTL (its fence action)*',
                'fence breached: *',
                'back home: the fence did its job')
        r.lines.last() == 'dsl-examples/fence.dolphin: completed'
    }

    @Timeout(100)
    def "a fleet of 300 over two links: every vehicle flies, is cut at 90 % on its own guard, lands; ids stay apart"() {
        when:
        def r = run('fleet')

        then:
        r.code == 0
        r.lines.contains('picked 300 vehicles')
        def cut = r.lines.findAll { it.startsWith('task patrol stopped on vehicle ') }*.substring('task patrol stopped on vehicle '.length())
        cut.size() == 300
        cut.toSet().size() == 300
        // the first of two vehicles with one id to be heard keeps the plain id, the other is ID@LINK
        (1..150).every { id -> cut.contains("$id".toString()) && cut.count { it ==~ /$id@[12]/ } == 1 }
        ScriptLines.inOrder(r.lines, 'all 300 patrols cut short at 90 %: DONE', 'all 300 vehicles landed', 'dsl-examples/fleet.dolphin: completed')
        r.lines.findAll { it ==~ /vehicle \S+: RTL, armed, .*task patrol stopped/ }.size() == 300
    }
}
