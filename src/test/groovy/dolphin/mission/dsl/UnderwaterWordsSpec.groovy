package dolphin.mission.dsl

import com.MAVLink.enums.MAV_CMD
import dolphin.core.Position
import dolphin.dsl.ScriptError
import dolphin.mission.flight.MissionTask
import dolphin.mission.model.MissionItem
import dolphin.mission.model.Underwater
import dolphin.platform.MAVLinkLanguage
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/**
 * The words of an underwater mission (docs/mission-commands.md, "maxDepth(metres) / dive(metres) /
 * surface()"): depths below the surface, the surface at home's height or sea level, and the bounds
 * checked as the mission is built, so `dolphin check` finds them.
 */
class UnderwaterWordsSpec extends Specification {

    static final String FILE = 'uuv.dolphin'

    ScriptHarness h = new ScriptHarness(0)

    def setup() {
        h.engine.addExtension(new MAVLinkLanguage())
    }

    List<MissionItem> items(String name) {
        (h.engine.variable(name) as MissionTask).mission().items(null)
    }

    def "dive goes straight down below the surface at sea level, move stays at that depth, surface() rises there"() {
        when:
        def r = h.run('''
            s = mission {
                maxDepth 20
                goPos 38.43490, -8.86118, 0
                dive 10
                move 40, 0
                surface()
            }
        ''', FILE)
        def i = items('s')
        def start = Position.fromDegrees(38.43490, -8.86118, 0)

        then:
        r.outcome == COMPLETED
        i*.command == [MAV_CMD.MAV_CMD_NAV_WAYPOINT] * 4 + [MAV_CMD.MAV_CMD_NAV_LAND]
        i*.z == [0f, 0f, -10f, -10f, 0f]
        i[2].position().distanceTo(start.atHeight(-10)) < 0.01
        Math.abs(start.displacementTo(i[3].position())[0] - 40) < 0.1
        i[4].position().distanceTo(i[3].position().atHeight(0)) < 0.01
        (h.engine.variable('s') as MissionTask).mission().underwater().get() == new Underwater(0, 20)
    }

    def "the surface is the mission's home height: a lake at 420 m"() {
        when:
        def r = h.run('''
            lake = mission {
                home 46.45, 6.55, 420
                maxDepth 50
                dive 30
            }
        ''', FILE)

        then:
        r.outcome == COMPLETED
        items('lake')[1].z == 390f
    }

    def "#kind is a script error at its line: #message"() {
        when:
        def r = h.run(source, FILE)
        ScriptError error = r.error

        then:
        r.outcome == SCRIPT_ERROR
        error.file == FILE
        error.line == source.readLines().findIndexOf { it.contains('<<') } + 1
        error.message.contains(message)

        where:
        kind                  | source                                                                                   || message
        'deeper than allowed' | "mission {\n maxDepth 20\n goPos 38.4349, -8.86118, 0\n dive 25 // <<\n}"                 || "item 2 (dive, NAV_WAYPOINT) is 25.0 m deep: deeper than the mission's limit, maxDepth 20 m"
        'above the water'     | "mission {\n maxDepth 20\n goPos 38.4349, -8.86118, 5 // <<\n}"                          || 'item 1 (goPos, NAV_WAYPOINT) is 5.0 m above the surface (the surface at 0.0 m): out of the water'
        'a dive without maxDepth' | "mission {\n goPos 38.4349, -8.86118, 0\n dive 10 // <<\n}"                            || "dive: say first that the mission is under water and how deep it may go: 'maxDepth METRES'"
        'surface without maxDepth' | "mission {\n goPos 38.4349, -8.86118, 0\n surface() // <<\n}"                         || 'surface: say first that the mission is under water'
        'home after maxDepth' | "mission {\n maxDepth 20\n home 38.4349, -8.86118, 0 // <<\n goPos 38.4349, -8.86118, 0\n}" || "home: name the mission's home before maxDepth"
        'a negative limit'    | "mission {\n maxDepth(-5) // <<\n goPos 38.4349, -8.86118, 0\n}"                         || 'maxDepth'
        'a negative dive'     | "mission {\n maxDepth 5\n goPos 38.4349, -8.86118, 0\n dive(-3) // <<\n}"                || 'dive'
    }

    /** A QGroundControl-style .waypoints file for a sub: home at sea level, waypoints relative to it at -5 and -{@code deepest}. */
    static File waypoints(double deepest) {
        File f = File.createTempFile('sub', '.waypoints')
        f.deleteOnExit()
        f.text = """QGC WPL 110
0\t1\t0\t16\t0\t0\t0\t0\t38.43462\t-8.86118\t0\t1
1\t0\t3\t16\t0\t0\t0\t0\t38.43490\t-8.86118\t-5\t1
2\t0\t3\t16\t0\t0\t0\t0\t38.43520\t-8.86118\t-${deepest}\t1
3\t0\t3\t21\t0\t0\t0\t0\t38.43520\t-8.86118\t0\t1
"""
        f
    }

    def "missionFromFile(maxDepth: 20) reuses a sub's plan made in QGroundControl: depths relative to home, checked as it is read"() {
        when:
        def r = h.run("sub = missionFromFile('${waypoints(12).path}', maxDepth: 20)", FILE)
        def m = (h.engine.variable('sub') as MissionTask).mission()

        then:
        r.outcome == COMPLETED
        m.underwater().get() == new Underwater(0, 20)
        m.items(null).drop(1)*.z == [-5f, -12f, 0f]
    }

    def "missionFromFile: an item deeper than maxDepth is a script error at its line, naming the file"() {
        given:
        File f = waypoints(30)

        when:
        def r = h.run("x = 1\nsub = missionFromFile('${f.path}', maxDepth: 20)", FILE)

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains("missionFromFile: ${f.path}: mission ${f.name - '.waypoints'}: item 2 (item, NAV_WAYPOINT) is 30.0 m deep")
    }
}
