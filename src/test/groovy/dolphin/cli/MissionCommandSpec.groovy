package dolphin.cli

import dolphin.core.VehiclelessPlatform
import dolphin.core.ManualClock
import dolphin.dsl.Engine
import dolphin.platform.MAVLinkLanguage
import dolphin.mission.dsl.MissionRecorder
import dolphin.mission.file.MavwpHarness
import dolphin.mission.model.Mission
import dolphin.mission.model.MissionItem
import dolphin.mission.file.PlanFile
import dolphin.mission.file.WaypointsFile
import groovy.json.JsonSlurper
import spock.lang.Specification
import spock.lang.TempDir
import spock.lang.Timeout

import java.nio.file.Files
import java.nio.file.Path

@Timeout(60)
class MissionCommandSpec extends Specification {

    static final String SURVEY = 'dsl-examples/survey.dolphin'

    @TempDir
    Path tmp

    Map dolphin(String... args) {
        def out = new StringWriter()
        def err = new StringWriter()
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(args)
        [code: code, out: out.toString(), err: err.toString()]
    }

    String script(String text) {
        Path f = tmp.resolve("script-${System.nanoTime()}.dolphin")
        Files.writeString(f, text)
        f.toString()
    }

    /** The missions a script builds, by name, with their items: built here with the engine, independently of the command. */
    static Map<String, List<MissionItem>> built(String path) {
        List<Mission> missions = []
        Engine engine = new Engine(new VehiclelessPlatform("dry run"), ManualClock.autoAdvancing())
        engine.addExtension(new MAVLinkLanguage())
        engine.addExtension(new MissionRecorder({ Mission m -> missions << m }))
        engine.run(Path.of(path)).await()
        missions.collectEntries { [it.id, it.items(null)] }
    }

    // ---- the table

    def "without --export each mission is printed as a table: seq, command, frame, p1..p4, lat, lon, alt"() {
        when:
        def r = dolphin('mission', SURVEY)
        def lines = r.out.readLines()

        then:
        r.code == 0
        lines[0] == 'mission survey: 13 items (item 0 is the home)'
        lines[1].split(/\s+/) == ['seq', 'command', 'frame', 'p1', 'p2', 'p3', 'p4', 'lat', 'lon', 'alt'] as String[]
        lines[2].trim().split(/\s+/) == ['0', 'NAV_WAYPOINT', 'GLOBAL_INT', '0', '0', '0', '0', '40.4442330', '-7.3752340', '820'] as String[]
        lines[3].trim().split(/\s+/) == ['1', 'NAV_TAKEOFF', 'GLOBAL_INT', '15', '0', '0', 'nan', '40.4442330', '-7.3752340', '920'] as String[]
        lines[14].trim().split(/\s+/)[0..2] == ['12', 'NAV_LAND', 'GLOBAL_INT']
        lines[15] == ''
        lines[16] == 'mission return home: 2 items (item 0 is the home)'
        lines.size() == 20
    }

    def "the table shows every item of every mission, as the missions' items say"() {
        given:
        def expected = built(SURVEY)

        when:
        def rows = dolphin('mission', SURVEY).out.readLines().findAll { it =~ /^\s*\d+\s/ }*.trim()*.split(/\s+/)

        then:
        rows.size() == expected.values().sum { it.size() }
        rows*.getAt(0)*.toInteger() == expected.values().collectMany { it*.seq() }
        rows*.getAt(1) == expected.values().collectMany { it*.commandName() }
        rows*.getAt(7) == expected.values().collectMany { it.collect { i -> String.format('%.7f', i.x() / 1e7) } }
    }

    def "the dry run ends at the first pick: the script halts there and says so on standard error"() {
        when:
        def r = dolphin('mission', SURVEY)

        then:
        r.code == 0
        r.err.contains('halted: pick: could not find 1 free vehicle(s)')
        r.err.contains('the dry run stops there: it has no vehicles to pick; 2 mission(s) built before it')
        !r.out.contains('halted')
    }

    def "the clock does not wait: a pick with a one-hour timeout ends the dry run at once"() {
        given:
        def s = script('''m = mission { name 'slow'; goPos 40.0, -7.0, 900 }
v = pick { timeout 3600 }
''')

        when:
        long start = System.nanoTime()
        def r = dolphin('mission', s)

        then:
        r.code == 0
        r.out.startsWith('mission slow: 2 items')
        (System.nanoTime() - start) / 1e9 < 20
    }

    def "a mission without home: item 0 is its first position, and the title says so"() {
        given:
        def s = script("m = mission { name 'nohome'; goPos 40.5, -7.25, 900; goPos 40.6, -7.25, 900 }\n")

        when:
        def r = dolphin('mission', s)
        def lines = r.out.readLines()

        then:
        r.code == 0
        lines[0] == 'mission nohome: 3 items (item 0 is the home: the first position, the mission names none)'
        lines[2].trim().split(/\s+/)[7..9] == ['40.5000000', '-7.2500000', '900']
    }

    def "position-less items show - for lat, lon and alt; the script's messages go to standard error"() {
        given:
        def s = script("""message 'building'
m = mission { name 'speedy'; home 40.5, -7.25, 800; speed 12.5; goPos 40.5, -7.2, 900 }
""")

        when:
        def r = dolphin('mission', s)
        def speedRow = r.out.readLines().find { it.contains('DO_CHANGE_SPEED') }

        then:
        r.code == 0
        speedRow.trim().split(/\s+/)[2] == 'MISSION'
        speedRow.trim().split(/\s+/)[7..9] == ['-', '-', '-']
        r.err.contains('building')
        !r.out.contains('building')
    }

    def "a script without missions: exit 0 and a note"() {
        when:
        def r = dolphin('mission', script("x = 1\n"))

        then:
        r.code == 0
        r.out.isEmpty()
        r.err.contains('builds no mission')
    }

    // ---- export

    def "--export #format writes one file per mission, named after it, into --out, and prints the paths"() {
        given:
        Path dir = tmp.resolve('out')

        when:
        def r = dolphin('mission', SURVEY, '--export', format, '--out', dir.toString())

        then:
        r.code == 0
        r.out.readLines() == [dir.resolve("survey.${format}").toString(), dir.resolve("return_home.${format}").toString()]
        Files.list(dir).count() == 2

        where:
        format << ['plan', 'waypoints', 'geojson']
    }

    def "exported .plan and .waypoints files import back to the missions' items"() {
        given:
        def expected = built(SURVEY)
        Path dir = tmp.resolve('round-trip')

        when:
        def plan = dolphin('mission', SURVEY, '--export', 'plan', '--out', dir.toString())
        def wp = dolphin('mission', SURVEY, '--export', 'waypoints', '--out', dir.toString())

        then:
        plan.code == 0
        wp.code == 0
        PlanFile.read(dir.resolve('survey.plan')) == expected.survey
        PlanFile.read(dir.resolve('return_home.plan')) == expected['return home']
        WaypointsFile.read(dir.resolve('survey.waypoints')) == expected.survey
        WaypointsFile.read(dir.resolve('return_home.waypoints')) == expected['return home']
        expected.survey.size() == 13
    }

    def "the GeoJSON export: a point per item of the survey and the flight path"() {
        given:
        Path dir = tmp.resolve('geo')

        when:
        dolphin('mission', SURVEY, '--export', 'geojson', '--out', dir.toString())
        def g = new JsonSlurper().parse(dir.resolve('survey.geojson').toFile())

        then:
        g.type == 'FeatureCollection'
        g.name == 'survey'
        g.features.count { it.geometry.type == 'Point' } == 13
        g.features.last().geometry.type == 'LineString'
        g.features.last().geometry.coordinates.size() == 13
        g.features[0].geometry.coordinates == [-7.375234, 40.444233, 820]
    }

    def "without --out the files go to the current directory"() {
        given:
        Path cwd = Path.of('').toAbsolutePath()
        def s = script("m = mission { name 'here-${System.nanoTime()}'; goPos 40.0, -7.0, 900 }\n")

        when:
        def r = dolphin('mission', s, '--export', 'waypoints')
        Path written = cwd.resolve(r.out.trim())

        then:
        r.code == 0
        !Path.of(r.out.trim()).absolute
        written.parent == cwd
        Files.exists(written)

        cleanup:
        if (written != null) {
            Files.deleteIfExists(written)
        }
    }

    def "file names: the mission name sanitised, and unique (case-insensitively)"() {
        given:
        def s = script('''a = mission { goPos 1, 2, 3 }
b = mission { name 'a/b c'; goPos 1, 2, 3 }
c = mission { name 'a/b c'; goPos 1, 2, 3 }
d = mission { name 'A_B C'; goPos 1, 2, 3 }
e = mission { name '../..'; goPos 1, 2, 3 }
f = mission { name 'Ré 7'; goPos 1, 2, 3 }
''')
        Path dir = tmp.resolve('names')

        when:
        def r = dolphin('mission', s, '--export', 'waypoints', '--out', dir.toString())

        then:
        r.code == 0
        r.out.readLines()*.replace(dir.toString() + File.separator, '') ==
                ['MissionPlan_line1.waypoints', 'a_b_c.waypoints', 'a_b_c-2.waypoints', 'A_B_C-3.waypoints',
                 'mission.waypoints', 'R_7.waypoints']
        Files.list(dir).count() == 6
    }

    def "fileName and uniqueName"() {
        expect:
        MissionCommand.fileName(name) == file

        where:
        name              | file
        'survey'          | 'survey'
        'return home'     | 'return_home'
        '  x  '           | 'x'
        '.hidden'         | 'hidden'
        'a..b'            | 'a..b'
        'C:\\missions\\1' | 'C_missions_1'
        '___'             | 'mission'
        ''                | 'mission'
    }

    def "uniqueName counts from 2"() {
        given:
        Set<String> taken = []

        expect:
        MissionCommand.uniqueName('m', '.plan', taken) == 'm.plan'
        MissionCommand.uniqueName('m', '.plan', taken) == 'm-2.plan'
        MissionCommand.uniqueName('M', '.plan', taken) == 'M-3.plan'
        MissionCommand.uniqueName('m', '.waypoints', taken) == 'm.waypoints'
    }

    def "a mission built twice (a function called twice) is exported once per build; the same object once"() {
        given:
        def s = script('''def make() { mission { name 'twice'; goPos 1, 2, 3 } }
a = make()
b = make()
''')

        when:
        def r = dolphin('mission', s, '--export', 'plan', '--out', tmp.resolve('twice').toString())

        then:
        r.code == 0
        r.out.readLines().collect { Path.of(it).fileName.toString() } == ['twice.plan', 'twice-2.plan']
    }

    // ---- errors

    def "a script error: exit 1 and file:line with what went wrong; nothing is written"() {
        given:
        def s = script(text)
        Path dir = tmp.resolve('never')

        when:
        def r = dolphin('mission', s, '--export', 'plan', '--out', dir.toString())

        then:
        r.code == 1
        r.err.contains("${s}:${line}")
        r.err.contains(fragment)
        r.out.isEmpty()
        !Files.list(dir).findAny().present

        where:
        text                                                                     | line  | fragment
        "x = 1\nm = mission { goPos 1, 2, 3 }\nfoo 3\n"                          | 3     | "unknown command 'foo'"
        "p = pos { lat 1 }\n\nm = mission {\n    name 'empty'\n}\n"              | 3     | "mission 'empty' has no items"
        "x = {\n"                                                                | '1:5' | "the '{' opened here is never closed"
    }

    def "bad command lines are usage errors: a message and exit 2"() {
        given:
        Path aFile = tmp.resolve('a-file')
        Files.writeString(aFile, 'x')

        when:
        def r = dolphin(args.collect { it.replace('A_FILE', aFile.toString()) } as String[])

        then:
        r.code == 2
        r.err.contains(message.replace('A_FILE', aFile.toString()))

        where:
        args                                                       | message
        ['mission', SURVEY, '--export', 'kml']                     | "Invalid value for option '--export': unknown format 'kml': expected one of plan, waypoints, geojson"
        ['mission', SURVEY, '--export']                            | "Missing required parameter for option '--export'"
        ['mission']                                                | "Missing required parameter: 'SCRIPT'"
        ['mission', 'no/such.dolphin']                             | 'dolphin mission: cannot read no/such.dolphin: no such file'
        ['mission', SURVEY, '--out', 'somewhere']                  | '--out needs --export'
        ['mission', SURVEY, '--export', 'plan', '--out', 'A_FILE'] | 'dolphin mission: cannot create the directory A_FILE: a file of that name is in the way'
        ['mission', SURVEY, '--frobnicate']                        | "Unknown option: '--frobnicate'"
    }

    def "a mission that cannot be written (a directory in the way): exit 2"() {
        given:
        Path dir = tmp.resolve('blocked')
        Files.createDirectories(dir.resolve('survey.plan'))

        when:
        def r = dolphin('mission', SURVEY, '--export', 'plan', '--out', dir.toString())

        then:
        r.code == 2
        r.err.contains("dolphin mission: cannot write ${dir.resolve('survey.plan')}")
    }

    // ---- acceptance: pymavlink loads what we export

    def "acceptance: the survey example exported as waypoints loads in pymavlink's mavwp with the same items"() {
        given:
        def expected = built(SURVEY)
        Path dir = tmp.resolve('acceptance')

        when:
        def r = dolphin('mission', SURVEY, '--export', 'waypoints', '--out', dir.toString())
        def files = r.out.readLines().collect { Path.of(it) }
        def loaded = MavwpHarness.load(files)

        then:
        r.code == 0
        files*.fileName*.toString() == ['survey.waypoints', 'return_home.waypoints']
        loaded*.count == [13, 2]
        MavwpHarness.differences(expected.survey, loaded[0]) == []
        MavwpHarness.differences(expected['return home'], loaded[1]) == []
    }

    def "a dry run that does not end is stopped after the time limit, with the missions built so far"() {
        given:
        def script = File.createTempFile('loop', '.dolphin')
        script.text = "m = mission { name 'x'; goPos 40, -7, 100 }\nwhile (true) { }\n"

        when:
        def out = new StringWriter()
        def err = new StringWriter()
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute('mission', script.path, '--time-limit', '1')

        then:
        code == 1
        err.toString().contains('the dry run was stopped after 1.0 s')
        err.toString().contains('1 mission(s) built by then')

        cleanup:
        script?.delete()
    }

    def "a mission's fence and rally points are printed and exported: in the plan, in files of their own beside a .waypoints, in the GeoJSON"() {
        given:
        String fence = 'dsl-examples/fence.dolphin'
        Path out = tmp.resolve('airspace')

        when:
        def printed = dolphin('mission', fence)
        def wpl = dolphin('mission', fence, '--export', 'waypoints', '--out', out.toString())
        def plan = dolphin('mission', fence, '--export', 'plan', '--out', out.toString())
        def geo = dolphin('mission', fence, '--export', 'geojson', '--out', out.toString())
        def mavwp = MavwpHarness.load([out.resolve('fenced_flight.fence.waypoints')], 'fence')[0]
        def rally = MavwpHarness.load([out.resolve('fenced_flight.rally.waypoints')], 'rally')[0]
        def json = new JsonSlurper().parse(out.resolve('fenced_flight.plan').toFile())
        def features = new JsonSlurper().parse(out.resolve('fenced_flight.geojson').toFile()).features

        then:
        [printed, wpl, plan, geo]*.code == [0, 0, 0, 0]
        printed.out.contains('fence of fenced flight: 2 regions (inclusion polygon of 4 vertices, exclusion circle of 30 m),'
                + ' return point, enabled at the start')
        printed.out.contains('rally points of fenced flight: 1')
        wpl.out.readLines()*.replace(out.toString() + '/', '') ==
                ['fenced_flight.waypoints', 'fenced_flight.fence.waypoints', 'fenced_flight.rally.waypoints']

        and: "pymavlink's fence and rally loaders read what we wrote"
        mavwp.items*.command == [5001] * 4 + [5004, 5000]
        mavwp.items*.param1.take(5) == [4, 4, 4, 4, 30]
        rally.items*.command == [5100]
        rally.items[0].z == 850

        and: 'the plan has them as QGroundControl does, heights above its home'
        json.geoFence.polygons*.inclusion == [true]
        json.geoFence.circles[0].circle.radius == 30
        json.geoFence.breachReturn[2] == 30
        json.rallyPoints.points == [[40.444, -7.375, 30]]

        and: 'the GeoJSON draws them'
        features.count { it.properties.fence == 'inclusion' } == 1
        features.count { it.properties.fence == 'exclusion' && it.properties.shape == 'circle' } == 1
        features.count { it.properties.rally == 0 } == 1
    }


    def "a mission read from a plane's plan is exported as a plane's plan, with the file's speeds"() {
        given:
        Path planePlan = tmp.resolve('plane.plan')
        Files.writeString(planePlan, new File('dsl-examples/square.plan').text.replace('"vehicleType": 2', '"vehicleType": 1')
                .replace('"cruiseSpeed": 15', '"cruiseSpeed": 22'))
        String s = script("m = missionFromFile('${planePlan}')")
        Path out = tmp.resolve('plane-out')

        when:
        def r = dolphin('mission', s, '--export', 'plan', '--out', out.toString())
        def json = new JsonSlurper().parse(out.resolve('plane.plan').toFile())

        then:
        r.code == 0
        json.mission.vehicleType == 1
        json.mission.cruiseSpeed == 22
        json.geoFence.polygons.size() == 1
        json.rallyPoints.points.size() == 1
    }

}
