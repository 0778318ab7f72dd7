package dolphin.mission.file

import dolphin.mission.model.MissionItem
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

import java.nio.file.Files
import java.nio.file.Path

import static MissionFileFixtures.*

/**
 * pymavlink's mavwp (the loader of MAVProxy's "wp load") reads the .waypoints files we write and
 * finds the same items (harness/mavwp_check.py, run with the project's venv).
 */
@Timeout(120)
class MavwpInteropSpec extends Specification {

    @Shared
    Path dir = Files.createTempDirectory('mavwp-interop')

    @Shared
    Map<String, List<MissionItem>> written = [
            mission : mission(),
            extremes: extremes(),
            random  : random(21, 300),
    ]

    /** mavwp's reading of each written file, by name. */
    @Shared
    Map<String, Map> loaded

    def setupSpec() {
        List<Path> files = written.collect { name, items ->
            Path f = dir.resolve("${name}.waypoints")
            WaypointsFile.write(f, items)
            f
        }
        List<Map> results = MavwpHarness.load(files)
        loaded = [written.keySet() as List, results].transpose().collectEntries()
    }

    def cleanupSpec() {
        dir?.toFile()?.deleteDir()
    }

    def "mavwp loads our file with the same items: #name"() {
        expect:
        loaded[name].count == written[name].size()
        MavwpHarness.differences(written[name], loaded[name]) == []

        where:
        name << ['mission', 'extremes', 'random']
    }

    def "mavwp sees the home on line 0 as a NAV_WAYPOINT with CURRENT 1 in the float frame GLOBAL"() {
        when:
        Map home = loaded.mission.items[0]

        then:
        home.seq == 0
        home.current == 1
        home.command == 16
        home.frame == 0
        home.x == 40.444233
        home.y == -7.375234
        home.z == 820
    }

    def "NaN parameters reach mavwp as NaN"() {
        expect: 'take-off and land have yaw NaN'
        loaded.mission.items[1].param4 == 'NaN'
        loaded.mission.items[6].param4 == 'NaN'
        loaded.mission.items[0].param4 == 0
    }

    def "the comparison notices a difference (it is not vacuous)"() {
        given:
        List<MissionItem> changed = new ArrayList<>(written.mission)
        MissionItem two = changed[2]
        changed[2] = new MissionItem(2, two.command(), two.frame(), two.param1(), two.param2(), two.param3(), two.param4(),
                two.x() + 1, two.y(), two.z(), two.autocontinue())

        expect:
        MavwpHarness.differences(changed, loaded.mission).size() == 1
        MavwpHarness.differences(changed, loaded.mission)[0].startsWith('item 2: x:')
        MavwpHarness.differences(written.mission.take(3), loaded.mission) == ['3 items written, mavwp loaded 7']
    }

    def "a file that is not QGC WPL 110 fails in mavwp too: the harness reports it"() {
        given:
        Path bad = dir.resolve('bad.waypoints')
        Files.writeString(bad, 'QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t1\t2\t3\n')

        when:
        MavwpHarness.load([bad])

        then:
        def e = thrown(AssertionError)
        e.message.contains('invalid waypoint line with 11 values')
    }
}
