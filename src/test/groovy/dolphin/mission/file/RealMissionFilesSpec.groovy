package dolphin.mission.file

import dolphin.mission.model.ItemText
import dolphin.mission.model.Fence
import dolphin.mission.model.FenceRegion
import dolphin.mission.model.MissionItem
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import groovy.json.JsonSlurper
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

import java.nio.file.Files
import java.nio.file.Path

/**
 * Every mission, fence and rally file of the corpus named by -Ddolphin.missionFiles (written by
 * ArduPilot's autotest, QGroundControl, MAVSDK and Mission Planner users, listed with their origin in
 * ORIGINS.tsv; the build's mission-files profile names it when it lies beside the repository) reads as pymavlink reads it (harness/mavwp_check.py: MAVWPLoader,
 * MissionItemProtocol_Fence, the rally loaders) or, for QGroundControl's JSON, as the JSON says;
 * survives a round trip through each format; and the files made wrong on purpose are refused in
 * one line naming the file. Skipped without the corpus; with it named, fails when a file is missing.
 */
@Timeout(300)
@Requires({ System.getProperty('dolphin.missionFiles') })
class RealMissionFilesSpec extends Specification {

    static final Path DIRECTORY = Path.of(System.getProperty('dolphin.missionFiles', '.'))

    /** MAVSDK's test plans made wrong on purpose, and what we say about them. */
    static final Map<String, String> REFUSED = [
            'qgroundcontrol_sample_wrong_mission_version.plan'   : 'mission.version 7 is not one QGroundControl reads',
            'qgroundcontrol_sample_with_survey_wrong_version.plan': 'mission.items[1]: survey version 9 is not one QGroundControl reads',
    ]

    @Shared
    List<Path> files = listed()

    /** Each readable file's contents, by path. */
    @Shared
    Map<Path, MissionFile> read = [:]

    /** pymavlink's reading of each text file, by path. */
    @Shared
    Map<Path, Map> pymavlink = [:]

    def setupSpec() {
        files.findAll { !REFUSED.containsKey(it.fileName.toString()) }.each { read[it] = MissionFile.read(it) }
        Map<String, List<Path>> byKind = read.keySet().findAll { !isJson(it) }.groupBy { kind(read[it]) }
        byKind.each { kind, paths ->
            List<Map> results = MavwpHarness.load(paths, kind == 'mission' ? null : kind)
            [paths, results].transpose().each { Path p, Map r -> pymavlink[p] = r }
        }
    }

    static List<Path> listed() {
        Path origins = DIRECTORY.resolve('ORIGINS.tsv')
        if (!Files.isRegularFile(origins)) {
            throw new IllegalStateException("the real mission files are missing: expected $origins")
        }
        // The rows whose files are under surveys/ (QGroundControl's complex items) are read by surveyPlans().
        Files.readAllLines(origins).findAll { it.trim() }.collect { line ->
            List<String> f = line.split('\t') as List
            String repo = f[0].split('@')[0].replace('/', '+')
            Path file = DIRECTORY.resolve(repo).resolve(f[1])
            if (!Files.exists(file) && !Files.exists(DIRECTORY.resolve('surveys').resolve(repo).resolve(f[1]))) {
                throw new IllegalStateException("ORIGINS.tsv names $file, which is missing")
            }
            Files.exists(file) ? file : null
        }.findAll()
    }

    /** The plans with QGroundControl's complex items, under surveys/ (docs/qgc-surveys.md §5). */
    static List<Path> surveyPlans() {
        Path surveys = DIRECTORY.resolve('surveys')
        if (!Files.isDirectory(surveys)) {
            throw new IllegalStateException("the survey plans are missing: expected $surveys")
        }
        Files.walk(surveys).withCloseable { s -> s.filter { it.toString().endsWith('.plan') }.sorted().toList() }
    }

    static boolean isJson(Path p) {
        Files.readString(p).replace('\uFEFF', '').trim().startsWith('{')
    }

    static String kind(MissionFile f) {
        f.hasMission() ? 'mission' : !f.fence().isEmpty() ? 'fence' : 'rally'
    }

    def "the list has the files of every origin and kind"() {
        expect:
        files.size() >= 80
        files.every { Files.isRegularFile(it) }
        read.values().count { !it.fence().isEmpty() } >= 5
        read.values().count { !it.rally().isEmpty() } >= 1
        read.keySet().count { isJson(it) } >= 10
    }

    def "#name reads as pymavlink reads it"() {
        given:
        MissionFile f = read[file]
        Map theirs = pymavlink[file]

        expect:
        theirs != null
        differences(items(f), theirs) == []

        where:
        file << listed().findAll { !REFUSED.containsKey(it.fileName.toString()) && !isJson(it) }
        name = DIRECTORY.relativize(file).toString()
    }

    def "#name reads as its JSON says"() {
        given:
        MissionFile f = read[file]
        Map json = new JsonSlurper().parse(file.toFile()) as Map
        Map mission = json.fileType == 'Plan' ? json.mission as Map : json
        List<Map> expected = flatten(mission.items as List<Map>)

        expect:
        f.mission().size() == expected.size() + 1
        home(mission) == [f.mission()[0].x(), f.mission()[0].y(), f.mission()[0].z()]
        [expected, f.mission().drop(1)].transpose().every { Map e, MissionItem o -> same(e, o) }
        f.vehicle().firmwareType() == (mission.firmwareType ?: mission.MAV_AUTOPILOT ?: 3)
        f.vehicle().vehicleType() == (mission.vehicleType ?: 2)
        f.fence().isEmpty() && f.rally().isEmpty() // none of these plans has either

        where:
        file << listed().findAll { !REFUSED.containsKey(it.fileName.toString()) && isJson(it) }
        name = DIRECTORY.relativize(file).toString()
    }

    def "#name survives a round trip through each format"() {
        given:
        MissionFile f = read[file]

        expect:
        if (f.hasMission()) {
            List<MissionItem> viaWpl = MissionFile.read(WaypointsFile.write(f.mission())).mission()
            MissionFile viaPlan = MissionFile.read(PlanFile.write(f))
            assert viaWpl == f.mission()
            assert viaPlan.mission().drop(1) == f.mission().drop(1)
            assert [viaPlan.mission()[0].x(), viaPlan.mission()[0].y(), viaPlan.mission()[0].z()] ==
                    [f.mission()[0].x(), f.mission()[0].y(), f.mission()[0].z()]
            assert viaPlan.vehicle() == f.vehicle()
        }
        if (!f.fence().isEmpty()) {
            assert MissionFile.read(WaypointsFile.writeItems(f.fence().items())).fence() == f.fence()
            assert regions(MissionFile.read(PlanFile.write(f)).fence()) == regions(f.fence())
        }
        if (!f.rally().isEmpty()) {
            assert MissionFile.read(WaypointsFile.writeItems(f.rally().items())).rally() == f.rally()
            assert MissionFile.read(PlanFile.write(f)).rally() == f.rally()
        }
        true

        where:
        file << listed().findAll { !REFUSED.containsKey(it.fileName.toString()) }
        name = DIRECTORY.relativize(file).toString()
    }

    def "#name: stored survey items read as they are, a structure scan regenerated: (N + 3) L + 4 items"() {
        given:
        MissionFile f = MissionFile.read(file)
        Map mission = (new JsonSlurper().parse(file.toFile()) as Map).mission as Map
        List<MissionItem> ours = f.mission().drop(1)
        int at = 0

        expect:
        mission.items.each { Map e ->
            if (e.type == 'ComplexItem' && e.TransectStyleComplexItem?.Items == null) {
                assert e.complexItemType == 'StructureScan'
                int n = e.polygon.size()
                int layers = e.Layers
                double h = e.CameraCalc.AdjustedFootprintFrontal
                List<MissionItem> scan = ours.subList(at, at + (n + 3) * layers + 4)
                List<Float> layerHeights = (0..<layers).collect {
                    (float) (e.StartFromTop ? e.StructureHeight - h / 2 - it * h : e.ScanBottomAlt + h / 2 + it * h)
                }
                assert [scan.first(), scan.last()].every {
                    it.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT && it.z() == (e.EntranceAltitude as float)
                }
                assert scan.findAll { it.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT }.drop(1).dropRight(1)*.z().unique() == layerHeights
                assert scan.every { it.command() != MAV_CMD.MAV_CMD_NAV_WAYPOINT || it.frame() == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT }
                at += scan.size()
            } else {
                flatten([e]).each { assert same(it, ours[at++]) }
            }
        }
        at == ours.size()

        where:
        file << surveyPlans()
        name = DIRECTORY.relativize(file).toString()
    }

    def "the survey plans have the structure scan of docs/qgc-surveys.md §5: 10 layers of 4 vertices"() {
        when:
        Path scan = surveyPlans().find { it.fileName.toString() == 'technopark_structure_scan.plan' }
        Map json = new JsonSlurper().parse(scan.toFile()) as Map

        then:
        json.mission.items.count { it.type == 'SimpleItem' } == 7
        MissionFile.read(scan).mission().size() == 1 + 7 + (4 + 3) * 10 + 4
    }

    def "#name, wrong on purpose, is refused in one line naming the file"() {
        when:
        MissionFile.read(file)

        then:
        IllegalArgumentException e = thrown()
        e.message.startsWith(file.toString() + ': ')
        e.message.contains(REFUSED[file.fileName.toString()])
        !e.message.contains('\n')

        where:
        file << listed().findAll { REFUSED.containsKey(it.fileName.toString()) }
        name = DIRECTORY.relativize(file).toString()
    }

    static List<MissionItem> items(MissionFile f) {
        f.hasMission() ? f.mission() : !f.fence().isEmpty() ? f.fence().items() : f.rally().items()
    }

    /** Command, frame, params, position and autocontinue as pymavlink loaded them (not CURRENT, which we drop). */
    static List<String> differences(List<MissionItem> ours, Map loaded) {
        List<Map> theirs = loaded.items as List<Map>
        if (theirs.size() != ours.size()) {
            return ["${ours.size()} items read, pymavlink loaded ${theirs.size()}".toString()]
        }
        List<String> diffs = []
        ours.eachWithIndex { MissionItem o, int i ->
            Map t = theirs[i]
            def check = { String what, boolean same -> if (!same) { diffs << "item $i: $what: ours $o, pymavlink $t".toString() } }
            check('command', t.command == o.command())
            check('frame', ItemText.itemFrame(t.frame as int) == o.frame()) // a file may name GLOBAL or GLOBAL_INT
            check('param1', MavwpHarness.sameFloat(t.param1, o.param1()))
            check('param2', MavwpHarness.sameFloat(t.param2, o.param2()))
            check('param3', MavwpHarness.sameFloat(t.param3, o.param3()))
            check('param4', MavwpHarness.sameFloat(t.param4, o.param4()))
            check('z', MavwpHarness.sameFloat(t.z, o.z()))
            if (loaded.units == 'degE7') {
                // the legacy loaders truncate lat * 1e7 with int(); we round the decimal exactly
                check('x', Math.abs((t.x as long) - o.x()) <= 1)
                check('y', Math.abs((t.y as long) - o.y()) <= 1)
            } else {
                check('x', MavwpHarness.sameDegrees(t.x, o.x()))
                check('y', MavwpHarness.sameDegrees(t.y, o.y()))
            }
            check('autocontinue', t.autocontinue == (o.autocontinue() ? 1 : 0))
        }
        diffs
    }

    /** The SimpleItems of a mission's items, ComplexItems replaced by their expanded items. */
    static List<Map> flatten(List<Map> items) {
        items.collectMany { it.type == 'ComplexItem' ? (it.TransectStyleComplexItem.Items as List<Map>) : [it] }
    }

    static List home(Map mission) {
        def h = mission.plannedHomePosition
        List c = h instanceof Map ? h.coordinate as List : h as List
        [degE7(c[0]), degE7(c[1]), c[2] as float]
    }

    /** One JSON item against ours: params (null as NaN) from params[7], or params[4] / param1..4 with coordinate. */
    static boolean same(Map e, MissionItem o) {
        List p = e.params != null ? (e.params as List) : [e.param1, e.param2, e.param3, e.param4]
        if (p.size() == 4) {
            p = p + (e.coordinate as List)
        }
        int frame = e.frame as int
        def z = p[6]
        if (e.AltitudeMode == PlanItems.ALTITUDE_CALC_ABOVE_TERRAIN && z == null) {
            frame = MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT
            z = e.Altitude
        }
        o.command() == (e.command as int) && ItemText.fileFrame(o.frame()) == frame &&
                [o.param1(), o.param2(), o.param3(), o.param4()] == p.take(4).collect { it == null ? Float.NaN : it as float } &&
                o.x() == degE7(p[4]) && o.y() == degE7(p[5]) && sameZ(z, o.z()) &&
                o.autocontinue() == (e.autoContinue == null || e.autoContinue) &&
                (o.command() != MAV_CMD.MAV_CMD_DO_JUMP || e.doJumpId == null)
    }

    static boolean sameZ(Object z, float ours) {
        z == null ? Float.isNaN(ours) : (z as float) == ours
    }

    static int degE7(Object degrees) {
        degrees == null ? 0 : new BigDecimal(degrees.toString()).movePointRight(7).setScale(0, java.math.RoundingMode.HALF_EVEN).intValueExact()
    }

    /** A fence's regions and return point's place, compared by degE7 and float radius. */
    static List regions(Fence f) {
        f.regions().collect { r ->
            r instanceof FenceRegion.Polygon
                    ? [r.inclusion(), r.vertices().collect { [MissionItem.degE7(it.latitudeDegrees()), MissionItem.degE7(it.longitudeDegrees())] }]
                    : [r.inclusion(), MissionItem.degE7(r.center().latitudeDegrees()), MissionItem.degE7(r.center().longitudeDegrees()), r.radius() as float]
        } + [f.returnPoint().map { [MissionItem.degE7(it.latitudeDegrees()), MissionItem.degE7(it.longitudeDegrees())] }.orElse(null)]
    }
}
