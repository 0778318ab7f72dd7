package dolphin.mission.dsl

import dolphin.mission.flight.MissionTask
import dolphin.testing.MissionLayer
import dolphin.core.Allocation
import dolphin.core.ConcurrentTask
import dolphin.core.EnvironmentException
import dolphin.core.NodeSet
import dolphin.core.Position
import dolphin.core.SequentialTask
import dolphin.dsl.ScriptError
import dolphin.dsl.ScriptResult
import dolphin.platform.MAVLinkLanguage
import dolphin.mission.model.Mission
import dolphin.mission.model.MissionItem
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import java.lang.reflect.Method
import java.lang.reflect.Modifier

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/**
 * The mission words in scripts (reference C.5, C.6, design §4, §5): missions built by the engine on
 * a platform without vehicles (the MAVLink language as an extension, virtual time), inspected with
 * Mission.items. Expected values come from the reference and the report; geometry is checked with
 * Position.displacementTo, independently of how the builder computed it.
 */
class MissionScriptSpec extends Specification {

    static final String FILE = 'missions/survey.dolphin'
    static final int WAYPOINT = 16, LOITER_UNLIM = 17, LAND = 21, TAKEOFF = 22, GLOBAL_INT = 5
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    ScriptHarness h = new ScriptHarness(0)

    def setup() {
        h.engine.addExtension(new MAVLinkLanguage())
    }

    private ScriptResult run(String source) {
        h.run(source, FILE)
    }

    private <T> T variable(String name) {
        (T) h.engine.variable(name)
    }

    private static void near(double[] ned, double north, double east) {
        assert Math.abs(ned[0] - north) < 0.1
        assert Math.abs(ned[1] - east) < 0.1
    }

    def "report Listing 2: the worked example of C.6.1 (heights AMSL; the first move is relative to the take-off)"() {
        when: 'the listing, as printed (its execute loop aside: there are no vehicles here)'
        def r = run('''
            homePos = location(40.444233, -7.375234, 820)
            takeOffLocation = location(40.444233, -7.375234, 1200)
            simpleMission = mission {
                 name "Survey Area"
                 home homePos
                 takeOff takeOffLocation
                 move 100, 200, 100
                 moveAndLoiterPos 200, 100, -20, 50
            }
            returnHome = mission {
                 name "Return to base"
                 home homePos
                 returnHomeAndLand()
            }
        ''')
        Mission simple = MissionLayer.missionOf(variable('simpleMission'))
        Mission back = MissionLayer.missionOf(variable('returnHome'))
        List<MissionItem> items = simple.items(null)

        then:
        r.outcome == COMPLETED
        simple.id == 'Survey Area'
        back.id == 'Return to base'

        and: 'seq 0 home placeholder at 820 m, seq 1 take-off at 1200 m'
        items*.seq() == [0, 1, 2, 3]
        items*.command() == [WAYPOINT, TAKEOFF, WAYPOINT, LOITER_UNLIM]
        items.every { it.frame() == GLOBAL_INT }
        items[0].x() == 404442330 && items[0].y() == -73752340 && items[0].z() == 820f
        items[1].x() == 404442330 && items[1].y() == -73752340 && items[1].z() == 1200f && items[1].param1() == 15f

        and: 'seq 2: 100 m N and 200 m E of the take-off point (over home; the take-off registers it), at 1200 + 100 = 1300 m'
        near(HOME.displacementTo(items[2].position()), 100, 200)
        items[2].z() == 1300f
        items[2].param2() == 50f

        and: 'seq 3: 200 m N and 100 m E of seq 2, 20 m lower (1280 m), radius 50, loiter forever'
        near(items[2].position().displacementTo(items[3].position()), 200, 100)
        items[3].z() == 1280f
        items[3].param3() == 50f

        and: 'the declared count is the emitted count; no ground-side commands'
        simple.missionPoints() == 4
        simple.nonMissionCommands().isEmpty()

        and: 'the return mission lands at home'
        back.items(null) == [new MissionItem(0, WAYPOINT, GLOBAL_INT, 0, 0, 0, 0, 404442330, -73752340, 820f, true),
                             new MissionItem(1, LAND, GLOBAL_INT, 0, 0, 0, Float.NaN, 404442330, -73752340, 820f, true)]
    }

    def "report Listing 3: surveys of 3000 x 10000 m with passes 500 m apart, from the take-off point, NORTH_EAST and SOUTH_EAST"() {
        when:
        def r = run('''
            homePos = location(40.444233, -7.375234, 820)
            takeOffLocation = location(40.444233, -7.375234, 1200)
            surveyNorth = mission {
                 name "Survey Area 1"
                 home homePos
                 takeOff takeOffLocation
                 surveyArea 3000, 10000, 500, "NORTH_EAST"
            }
            surveySouth = mission {
                 name "Survey Area 2"
                 home homePos
                 takeOff takeOffLocation
                 surveyArea 3000, 10000, 500, "SOUTH_EAST"
            }
        ''')
        List<MissionItem> north = MissionLayer.missionOf(variable('surveyNorth')).items(null)
        List<MissionItem> south = MissionLayer.missionOf(variable('surveySouth')).items(null)

        then: 'N = 10000 / 500 + 1 = 21 passes: 42 survey items after home and take-off, all counted'
        r.outcome == COMPLETED
        north.size() == 44
        MissionLayer.missionOf(variable('surveyNorth')).missionPoints() == 44
        north*.seq() == (0..43).toList()

        and: 'the first leg is 3025 m north (south) of the take-off point over home, the last lane 20 x 500 m east, and the survey ends over home at the take-off height'
        near(HOME.displacementTo(north[2].position()), 3025, 0)
        near(HOME.displacementTo(south[2].position()), -3025, 0)
        Math.abs(HOME.displacementTo(north[42].position())[1] - 10000) < 10
        north[43].x() == 404442330 && north[43].y() == -73752340
        north.drop(2).every { it.z() == 1200f && it.param2() == 25f }
    }

    def "the words come with the MAVLink language: 'dolphin check' accepts them, a platform without it does not"() {
        given:
        def source = '''
            base = pos { lat 41.185781; lon(-8.70606486); hae 100 }
            offset = moveDistance { north 10; east 20 }
            p = move(base, offset)
            q = move(base) { down(-5) }
            m = mission { home base; allowBelowHome true; goPos p; goPos q; surveyArea 100, 100 }
        '''
        def bare = new ScriptHarness(0)

        expect:
        h.engine.check(source, FILE) == []
        run(source).outcome == COMPLETED
        bare.run(source).error.message.startsWith("unknown command 'pos'")
    }

    def "IDEs see the builders: #word's closure is @DelegatesTo(#delegate, DELEGATE_FIRST)"() {
        given:
        Method m = MissionDsl.getMethod(word, Closure)
        DelegatesTo d = m.parameterAnnotations[0].find { it instanceof DelegatesTo } as DelegatesTo

        expect:
        d.value() == delegate
        d.strategy() == Closure.DELEGATE_FIRST
        m.returnType == returns

        where:
        word           || delegate        | returns
        'mission'      || MissionBuilder  | MissionTask
        'pos'          || PositionBuilder | Position
        'moveDistance' || NedBuilder      | NedOffset
    }

    def "inside mission { } the commands come first; script variables, methods and words stay visible"() {
        when:
        def r = run('''
            def local = 41.185781
            lonVar = -8.70606486
            def speed(x) { 'the script speed' }
            def here() { location(41.184742, -8.704601, 150) }
            m = mission {
                goPos local, lonVar, 100     // a def variable and a binding variable
                goPos here()                 // a script method
                message "building"           // a core word
                speed 12                     // the mission command, not the script's method
                assigned = 5                 // assignments go to the script
            }
        ''')
        Mission m = MissionLayer.missionOf(variable('m'))

        then:
        r.outcome == COMPLETED
        m.items(null)*.command() == [WAYPOINT, WAYPOINT, WAYPOINT, 178]
        m.items(null)[1].x() == 411857810
        m.items(null)[2].x() == 411847420
        h.messages.contains('building')
        variable('assigned') == 5
    }

    def "pos, move and moveDistance (reference C.5): degrees, metres, heights AMSL"() {
        when:
        def r = run('''
            a = pos { lat 41.185781; lon(-8.70606486); hae 100 }
            b = pos { lat 41.185781; lon(-8.70606486); height 100 }
            zero = pos { }
            d = moveDistance { north 100; east(-50); down(-20) }
            nothing = moveDistance { }
            c = move(a, d)
            e = move a, { north 100; east(-50); down(-20) }
            inMission = mission { home a; goPos move(a) { north 10; down(-10) } }
        ''')
        Position a = variable('a')

        then:
        r.outcome == COMPLETED
        a == Position.fromDegrees(41.185781, -8.70606486, 100)
        variable('b') == a
        variable('zero') == new Position(0, 0, 0)
        variable('d') == new NedOffset(100, -50, -20)
        variable('nothing') == new NedOffset(0, 0, 0)
        variable('c') == variable('e')
        near(a.displacementTo(variable('c')), 100, -50)
        ((Position) variable('c')).hae() == 120d

        and: 'inside a mission, move(position) { } is still the position word: it adds no item'
        Mission m = MissionLayer.missionOf(variable('inMission'))
        m.items(null).size() == 2
        near(a.displacementTo(m.items(null)[1].position()), 10, 0)
    }

    def "a mission is a platform task: it composes with every operator and allocates a vehicle per occurrence"() {
        given:
        h.platform.addNode('1')
        h.platform.addNode('2')

        when:
        def r = run('''
            m1 = mission { goPos 41.185781, -8.70606486, 100 }
            m2 = mission { goPos 41.184742, -8.704601, 150 }
            seq = m1 / { false } >> m2
            both = m1 | m2
            twice = m1 | m1
        ''')
        def both = variable('both')
        def twice = variable('twice')
        def seq = variable('seq')
        Allocation a = new Allocation()
        Allocation b = new Allocation()
        Allocation c = new Allocation()
        NodeSet pool = h.platform.connectedNodes

        then:
        r.outcome == COMPLETED
        seq instanceof SequentialTask
        seq.allocate(h.platform.connectedNodes, c)
        c.allNodes()*.id == ['1']                     // both parts of a sequence may use one vehicle
        both instanceof ConcurrentTask
        both.allocate(pool, a)
        a.child(0).nodes()*.id == ['1']
        a.child(1).nodes()*.id == ['2']
        pool.size() == 0
        twice.allocate(h.platform.connectedNodes, b)
        b.allNodes()*.id == ['1', '2']

        and: 'each occurrence gets its own executor, which flies the mission'
        variable('m1').executor instanceof dolphin.mission.flight.MissionExecutor
        !variable('m1').executor.is(variable('m1').executor)
    }

    def "every command of C.6 rows 1 to 30, allowBelowHome, fence, rally, the underwater and the mapping words, the flight limits, the vertical and runway words, is a builder method, has its forms for errors and is documented"() {
        given:
        Set<String> methods = MissionBuilder.declaredMethods
                .findAll { Modifier.isPublic(it.modifiers) && !it.synthetic && !it.name.startsWith('\$') }*.name
                .toSet() - ['methodMissing', 'getProperty', 'setProperty', 'getMetaClass', 'setMetaClass', 'invokeMethod']
        String doc = new File('docs/mission-commands.md').text

        expect:
        methods == MissionBuilder.COMMANDS.keySet()
        methods == ['name', 'home', 'goPos', 'takeOff', 'takeOffWithYaw', 'move', 'moveFromHome', 'moveAndLoiterPos',
                    'moveAndLoiterTurns', 'moveAndLoiterTime', 'moveAndLoiterFromHome', 'moveAndLoiterTurnsFromHome',
                    'moveAndLoiterTimeFromHome', 'loiterPos', 'loiterTurns', 'loiterTime', 'landingPoint', 'returnHome',
                    'returnHomeAndLoiter', 'returnHomeAndLand', 'speed', 'altitude', 'delay', 'surveyArea', 'capturePhoto',
                    'captureSeveralPhotos', 'captureUntilStop', 'stopCapturing', 'jumpToItem', 'allowBelowHome', 'fence',
                    'rally', 'maxDepth', 'dive', 'surface', 'survey', 'corridorScan', 'structureScan', 'stallLimit',
                    'takeoverTimeout', 'takeOffVertically', 'takeOffOnRunway', 'landVertically', 'landOnRunway',
                    'returnHomeAndLandVertically', 'returnHomeAndLandOnRunway'].toSet()
        methods.every { doc.contains("`${it}(") || doc.contains("`${it} {") }
    }

    def "stallLimit and takeoverTimeout are the mission's own flight limits; without them the run's apply"() {
        when:
        def r = run("""
            limited = mission {
                stallLimit 90
                takeoverTimeout 5.minutes
                goPos 41, -8, 100
            }
            plain = mission { goPos 41, -8, 100 }
            """)

        then:
        r.outcome == COMPLETED
        def limits = (h.engine.variable('limited') as MissionTask).mission().limits()
        limits.stall().get() == java.time.Duration.ofSeconds(90)
        limits.takeover().get() == java.time.Duration.ofMinutes(5)
        (h.engine.variable('plain') as MissionTask).mission().limits() == dolphin.mission.model.FlightLimits.RUN
    }

    def "bad input is a script error naming the command, the file and the line: #kind"() {
        when:
        def r = run(source)
        ScriptError error = r.error

        then:
        r.outcome == SCRIPT_ERROR
        error.file == FILE
        error.line == source.readLines().findIndexOf { it.contains('<<') } + 1
        error.message == message
        h.messages.any { it.startsWith("${FILE}:${error.line}:") && it.endsWith(": ${message}") }

        where:
        kind                          | source                                                                                          || message
        'wrong argument type'         | "m = mission {\n  goPos 'Porto' // <<\n}"                                                       || "goPos: expected (lat, lon[, hae]) or (position), got (String)"
        'too few arguments'           | "m = mission {\n  goPos 41 // <<\n}"                                                            || "goPos: expected (lat, lon[, hae]) or (position), got (Integer)"
        'too many arguments'          | "m = mission {\n  home 41, -8\n  move 1, 2, 3, 4 // <<\n}"                                      || "move: expected (north, east[, up]) or (position, offset) or (position, { offset }), got (Integer, Integer, Integer, Integer)"
        'no-argument command'         | "m = mission {\n  home 41, -8\n  returnHome 5 // <<\n}"                                         || "returnHome: expected (), got (Integer)"
        'unknown survey direction'    | "m = mission {\n  home 41, -8\n  surveyArea 1000, 500, 50, 'EAST' // <<\n}"                     || "surveyArea: unknown direction 'EAST': expected NORTH_EAST, NORTH_WEST, SOUTH_EAST or SOUTH_WEST"
        'direction without spacing'   | "m = mission {\n  home 41, -8\n  surveyArea 1000, 500, 'north_east' // <<\n}"                   || "surveyArea: unknown direction 'north_east': expected NORTH_EAST, NORTH_WEST, SOUTH_EAST or SOUTH_WEST"
        'negative radius'             | "m = mission {\n  loiterTurns 41, -8, 100, 3, -5 // <<\n}"                                      || "loiterTurns: the radius must not be negative, got -5"
        'negative radius, relative'   | "m = mission {\n  home 41, -8\n  moveAndLoiterPos 10, 10, 0, -1.5 // <<\n}"                     || "moveAndLoiterPos: the radius must not be negative, got -1.5"
        'negative turns'              | "m = mission {\n  loiterTurns 41, -8, 100, -2 // <<\n}"                                         || "loiterTurns: the number of turns must be at least 1, got -2"
        'fractional turns'            | "m = mission {\n  loiterTurns 41, -8, 100, 2.5 // <<\n}"                                        || "loiterTurns: the number of turns must be a whole number, got 2.5"
        'negative photo count'        | "m = mission {\n  captureSeveralPhotos(-1) // <<\n}"                                            || "captureSeveralPhotos: the number of photos must be at least 1, got -1"
        'negative loiter time'        | "m = mission {\n  loiterTime 41, -8, 100, -30 // <<\n}"                                         || "loiterTime: the time must not be negative, got -30"
        'negative delay'              | "m = mission {\n  delay(-1) // <<\n}"                                                           || "delay: the time must not be negative, got -1"
        'zero interval'               | "m = mission {\n  captureUntilStop 0 // <<\n}"                                                  || "captureUntilStop: the interval must be positive, got 0"
        'latitude out of range'       | "m = mission {\n  goPos 95, 10 // <<\n}"                                                        || "goPos: the latitude must be between -90 and 90 degrees, got 95"
        'longitude out of range'      | "m = mission {\n  home 41, 200 // <<\n}"                                                        || "home: the longitude must be between -180 and 180 degrees, got 200"
        'NaN height'                  | "m = mission {\n  goPos 41, -8, Double.NaN // <<\n}"                                            || "goPos: the height must be a finite number, got NaN"
        'null position'               | "p = null\nm = mission {\n  takeOff p // <<\n}"                                                  || "takeOff: the position is null (a variable that holds no position?)"
        'speed type'                  | "m = mission {\n  speed 12, 7 // <<\n}"                                                         || "speed: the speed type must be 0 (airspeed), 1 (ground speed), 2 (climb) or 3 (descent), got 7"
        'non-positive speed'          | "m = mission {\n  speed 0 // <<\n}"                                                             || "speed: the speed must be positive, got 0"
        'a stall limit of 0'          | "m = mission {\n  stallLimit 0 // <<\n  goPos 41, -8, 100\n}"                                || "stallLimit: the stall limit must be positive, got 0"
        'a negative takeover timeout' | "m = mission {\n  takeoverTimeout(-1.minutes) // <<\n  goPos 41, -8, 100\n}"                  || "takeoverTimeout: the takeover timeout must be positive, got -60.0"
        'land mode'                   | "m = mission {\n  landingPoint 41, -8, 0, 0, 5 // <<\n}"                                        || "landingPoint: the land mode must be 0 (disabled), 1 (opportunistic) or 2 (required), got 5"
        'survey spacing'              | "m = mission {\n  home 41, -8\n  surveyArea 1000, 500, 0 // <<\n}"                              || "surveyArea: the spacing must be positive, got 0"
        'survey too large'            | "m = mission {\n  home 41, -8\n  surveyArea 1000, 100000, 1 // <<\n}"                           || "surveyArea: a width of 100000.0 m with passes 1.0 m apart makes more than 32767 passes (2 items each); a MAVLink mission holds at most 65535 items"
        'relative without a position' | "m = mission {\n  loiterPos location(41, -8, 100)\n  move 100, 0 // <<\n}"                       || "move: there is no position to start from yet: name the mission's home ('home lat, lon, hae') or go to a position (goPos, ...) before it"
        'below home + 2 m'            | "m = mission {\n  home 41, -8, 100\n  takeOff location(41, -8, 120)\n  move 50, 0, -19 // <<\n}" || "mission MissionPlan_line1: item 2 (move, NAV_WAYPOINT) is 1.0 m above home (home at 100.0 m): lower than the 2 m clearance, into the ground or nearly; only landings go lower. Raise it, or write 'allowBelowHome true' in the mission if this is intended"
        'a take-off into the ground'  | "m = mission {\n  home 41, -8, 100\n  takeOff location(41, -8, 100) // <<\n  move 50, 0, 20\n}" || "mission MissionPlan_line1: item 1 (takeOff, NAV_TAKEOFF) is 0.0 m above home (home at 100.0 m): lower than the 2 m clearance, into the ground or nearly; only landings go lower. Raise it, or write 'allowBelowHome true' in the mission if this is intended"
        'returnHome with no height'   | "m = mission {\n  home 41, -8, 100\n  returnHome() // <<\n}"                                     || "returnHome: there is no height to return at yet: the mission goes nowhere before it; go somewhere first (takeOff, goPos, move, ...), or use returnHomeAndLand()"
        'fromHome without home'       | "m = mission {\n  goPos 41, -8, 100\n  moveFromHome 100, 0, 0 // <<\n}"                          || "moveFromHome: the mission has no home yet: write 'home lat, lon, hae' before it"
        'returnHome without home'     | "m = mission {\n  goPos 41, -8, 100\n  returnHomeAndLand() // <<\n}"                             || "returnHomeAndLand: the mission has no home yet: write 'home lat, lon, hae' before it"
        'two homes'                   | "m = mission {\n  home 41, -8, 10\n  home 42, -8 // <<\n}"                                      || "home: this mission already has a home, (41.000000°, -8.000000°, 10.000); a mission has one home"
        'no items'                    | "m = mission { // <<\n  name 'Empty'\n  home 41, -8\n}"                                         || "mission 'Empty' has no items: expected at least one mission command (goPos, move, takeOff, surveyArea, ...)"
        'no items, default name'      | "\nm = mission { } // <<"                                                                        || "mission 'MissionPlan_line2' has no items: expected at least one mission command (goPos, move, takeOff, surveyArea, ...)"
        'jump first'                  | "m = mission {\n  jumpToItem 1 // <<\n  goPos 41, -8, 100\n}"                                   || "jumpToItem: no mission item before it: the jump happens when the item before it is reached"
        'jump past the end'           | "m = mission {\n  goPos 41, -8, 100\n  jumpToItem 2 // <<\n}"                                   || "jumpToItem: there is no item 2: mission 'MissionPlan_line1' has items 0 to 1 (0 is home)"
        'jump negative'               | "m = mission {\n  goPos 41, -8, 100\n  jumpToItem(-1) // <<\n}"                                 || "jumpToItem: the item must not be negative, got -1"
        'jump repetitions'            | "m = mission {\n  goPos 41, -8, 100\n  jumpToItem 1, 0 // <<\n}"                                || "jumpToItem: the number of repetitions must be at least 1, got 0"
        'typo'                        | "m = mission {\n  takeoff location(41, -8, 100) // <<\n}"                                        || "unknown mission command 'takeoff'; did you mean 'takeOff' or 'takeOffWithYaw' or 'takeOffOnRunway'?"
        'command without ()'          | "m = mission {\n  home 41, -8\n  returnHome // <<\n}"                                           || "'returnHome' is a command of mission { }, but Groovy read it as a variable here: write it with its arguments, as in returnHome()"
        'mission move outside'        | "move 100, 200 // <<"                                                                            || "move: expected (position, { north n; east e; down d }) or (position, moveDistance { ... }), got (Integer, Integer); move(north, east[, up]) is a mission command, for use inside mission { }"
        'pos latitude'                | "p = pos { lat 95 } // <<"                                                                       || "pos: the latitude must be between -90 and 90 degrees, got 95"
        'negative without ()'         | "d = moveDistance { down -3 } // <<"                                                             || "moveDistance: 'down' needs its value, e.g. 'down 10'; a negative value needs parentheses, e.g. 'down(-10)' (Groovy reads 'down -10' as 'down minus 10')"
    }
}
