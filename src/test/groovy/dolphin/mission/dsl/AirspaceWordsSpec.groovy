package dolphin.mission.dsl

import dolphin.testing.MissionLayer
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.core.Position
import dolphin.dsl.ScriptError
import dolphin.dsl.ScriptResult
import dolphin.platform.MAVLinkLanguage
import dolphin.mission.model.FenceRegion
import dolphin.mission.model.Mission
import dolphin.mission.model.MissionItem
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code fence { }} and {@code rally} in {@code mission { }} (docs/airspace.md), in scripts without vehicles. */
class AirspaceWordsSpec extends Specification {

    static final String FILE = 'missions/fenced.dolphin'
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    ScriptHarness h = new ScriptHarness(0)

    def setup() {
        h.engine.addExtension(new MAVLinkLanguage())
    }

    private ScriptResult run(String source) {
        h.run(source, FILE)
    }

    def "a fence of polygons and circles, a return point, enable, and rally points become the mission's airspace"() {
        when:
        def r = run('''
            homePos = location(40.444233, -7.375234, 820)
            m = mission {
                home homePos
                fence {
                    inclusion polygon(move(homePos) { north 100 }, move(homePos) { east 100 }, move(homePos) { north(-100) })
                    exclusion circle(move(homePos) { north 20; east 20 }, 12.5)
                    exclusion polygon(move(homePos) { north 50; east 10 }, move(homePos) { north 60; east 10 }, move(homePos) { north 55; east 20 })
                    returnPoint location(40.444233, -7.375234, 850)
                    enable true
                }
                rally location(40.4443, -7.3753, 850.4), location(40.4441, -7.3751, 849.6)
                takeOff location(40.444233, -7.375234, 850)
            }
            plain = mission { home homePos; takeOff location(40.444233, -7.375234, 850) }
        ''')
        Mission m = MissionLayer.missionOf(h.engine.variable('m'))
        Mission plain = MissionLayer.missionOf(h.engine.variable('plain'))

        then:
        r.outcome == COMPLETED
        m.fenceEnabled()
        m.fence().regions()*.describe() == ['inclusion polygon of 3 vertices', 'exclusion polygon of 3 vertices',
                                           'exclusion circle of 12.5 m']
        m.fence().items()*.command() == [MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION] * 3 +
                [MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION] * 3 +
                [MAV_CMD.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION, MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT]
        m.fence().returnPoint().get().hae() == 850d
        m.fence().breachedBy(HOME.displace(150, 0, 0)).isPresent()
        !m.fence().breachedBy(HOME.displace(0, 10, 0)).isPresent()
        m.fence().breachedBy(HOME.displace(20, 25, 0)).get() instanceof FenceRegion.Circle

        and: 'rally points above mean sea level, at whole metres as ArduPilot keeps them'
        m.rally().items()*.frame() == [MAV_FRAME.MAV_FRAME_GLOBAL_INT] * 2
        m.rally().items()*.z() == [850f, 850f]

        and: 'a mission without them has none, and its fence stays off'
        plain.fence().isEmpty() && plain.rally().isEmpty() && !plain.fenceEnabled()
    }

    def "a fence or rally point that cannot be flown is a script error at its line: #message"() {
        when:
        def r = run(source)
        ScriptError error = r.error

        then:
        r.outcome == SCRIPT_ERROR
        error.file == FILE
        error.line == source.readLines().findIndexOf { it.contains('<<') } + 1
        error.message.contains(message)

        where:
        source                                                                                                   | message
        'mission {\n fence {\n inclusion polygon(location(1, 2, 3), location(1, 3, 3)) // <<\n }\n goPos 1, 2, 30 }' | 'fence: polygon needs at least 3 positions, got 2'
        'mission {\n fence {\n exclusion circle(location(1, 2, 3), 0) // <<\n }\n goPos 1, 2, 30 }'               | 'fence: circle radius must be above 0 m, got 0'
        'mission {\n fence {\n inclusion 5 // <<\n }\n goPos 1, 2, 30 }'                                         | 'fence: expected inclusion polygon(p1, p2, p3, ...) or inclusion circle(center, radius)'
        'mission {\n fence { // <<\n enable true\n }\n goPos 1, 2, 30 }'                                        | 'fence: no region'
        'mission {\n home 1, 2, 100\n rally location(1, 2, 101) // <<\n goPos 1, 2, 130 }'                       | 'rally: the rally point (1.000000°, 2.000000°, 101.000) is lower than home plus 2 m'
        'mission {\n rally() // <<\n goPos 1, 2, 30 }'                                                           | 'rally: expected one or more positions'
    }

    def "rally points below home are the script's choice with allowBelowHome"() {
        expect:
        run('m = mission { home 1, 2, 100; allowBelowHome true; rally location(1, 2, 90); goPos 1, 2, 130 }').outcome == COMPLETED
        (MissionLayer.missionOf(h.engine.variable('m'))).rally().items()[0].z() == 90f
    }

    def "missionFromFile gives a mission task with the file's fence and rally points, its home left to the vehicle"() {
        when:
        def r = run("m = missionFromFile('dsl-examples/square.plan', enableFence: true)\nplain = missionFromFile('${RAW}')")
        Mission m = MissionLayer.missionOf(h.engine.variable('m'))
        Mission plain = MissionLayer.missionOf(h.engine.variable('plain'))

        then:
        r.outcome == COMPLETED
        m.id == 'square'
        m.home == null
        m.items(HOME).size() == 6
        m.items(HOME)[1].command() == MAV_CMD.MAV_CMD_NAV_TAKEOFF
        m.fence().regions().size() == 1
        m.fenceEnabled()
        m.rally().size() == 1
        plain.items(HOME).size() == 7
        plain.items(HOME)[6].command() == MAV_CMD.MAV_CMD_DO_JUMP
        plain.fence().isEmpty() && !plain.fenceEnabled()
        !plain.belowHomeAllowed()
        run("low = missionFromFile('${RAW}', allowBelowHome: true)").outcome == COMPLETED
        (MissionLayer.missionOf(h.engine.variable('low'))).belowHomeAllowed()
        h.messages.any { it.contains('read 5 mission items, a fence of 1 region') }
    }

    def "a file that cannot give a mission is a script error at the missionFromFile line: #message"() {
        when:
        def r = run("x = 1\nm = missionFromFile(${args})")

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains(message)

        where:
        args                                              | message
        "'no/such.plan'"                                  | 'missionFromFile: no file no/such.plan'
        "'${FENCE_ONLY}'"                                 | 'holds a fence but no mission'
        "'${WRONG}'"                                      | 'mission.version 7 is not one QGroundControl reads'
        "'dsl-examples/square.plan', fence: true"         | "missionFromFile: unknown option 'fence' (expected enableFence, allowBelowHome, maxDepth, name)"
    }

    /** Small files of each kind, written for these specs. */
    static final String FILES = 'src/test/resources/missions/'
    static final String RAW = FILES + 'circuit.waypoints'
    static final String FENCE_ONLY = FILES + 'fence-only.txt'
    static final String WRONG = FILES + 'wrong-version.plan'

}
