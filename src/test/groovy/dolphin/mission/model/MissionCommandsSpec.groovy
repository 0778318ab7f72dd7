package dolphin.mission.model

import dolphin.core.Position
import dolphin.mission.dsl.MissionDsl
import spock.lang.Specification

/**
 * Every command of reference C.6 (rows 1 to 30) and every optional-argument form, as the MAVLink
 * item it produces: command id, frame, p1 to p4, x and y in degE7, z in metres above mean sea level,
 * seq. Expected values are the reference's (C.6), changed where design §5 and F-8/F-10 say so
 * (speed, delay, camera, altitude), written here as numbers, not taken from the code. Relative
 * positions are checked with Position.displacementTo from the reference position back to the item.
 * The reference's test positions lie below the report's home, so these missions allow it
 * ({@code allowBelowHome true}); HeightCheckSpec tests the check itself.
 */
class MissionCommandsSpec extends Specification {

    // MAV_CMD ids and MAV_FRAME values (MAVLink common.xml; the reference's C.6 table)
    static final int WAYPOINT = 16, LOITER_UNLIM = 17, LOITER_TURNS = 18, LOITER_TIME = 19, LAND = 21, TAKEOFF = 22
    static final int NAV_DELAY = 93, DO_CHANGE_SPEED = 178, DO_SET_HOME = 179, IMAGE_START_CAPTURE = 2000, IMAGE_STOP_CAPTURE = 2001
    static final int GLOBAL_INT = 5, MISSION = 2
    static final float NaN = Float.NaN

    /** Home of the report's Listing 2 (820 m AMSL). */
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final List<Integer> HOME7 = [404442330, -73752340]
    /** APDL and B1 of the reference's WGS-84 test vectors (B.5), at 100 m and 150 m. */
    static final Position A = Position.fromDegrees(41.185781, -8.70606486, 100)
    static final List<Integer> A7 = [411857810, -87060649]
    static final Position B = Position.fromDegrees(41.184742, -8.704601, 150)
    static final List<Integer> B7 = [411847420, -87046010]
    static final List<Integer> NONE = [0, 0]

    /** An expected horizontal position: north and east metres from a reference position. */
    static class Rel {
        final String name
        final Position from
        final double north, east

        Rel(String name, Position from, double north, double east) {
            this.name = name
            this.from = from
            this.north = north
            this.east = east
        }

        String toString() { "${north} N ${east} E of ${name}" }
    }

    static Rel fromA(double n, double e) { new Rel('A', A, n, e) }

    static Rel fromB(double n, double e) { new Rel('B', B, n, e) }

    static Rel fromHome(double n, double e) { new Rel('HOME', HOME, n, e) }

    /** Row sources are compiled as closures, with A, B and HOME in scope. */
    static final GroovyShell SHELL = new GroovyShell(new Binding([A: A, B: B, HOME: HOME]))

    /** Every row's mission: home HOME (no item of its own), goPos A (seq 1), then the row's command from seq 2; below home allowed. */
    /** The mission that {@code mission { }} builds, without its task. */
    static Mission missionOf(Closure body) {
        MissionDsl.mission(body).mission()
    }

    static Mission withPrefix(String source) {
        withPrefix((Closure) SHELL.evaluate("return { -> ${source} }"))
    }

    static Mission withPrefix(Closure row) {
        missionOf {
            home HOME
            allowBelowHome true
            goPos 41.185781, -8.70606486, 100
            Closure c = (Closure) row.clone()
            c.delegate = delegate
            c.resolveStrategy = Closure.DELEGATE_FIRST
            c.call()
        }
    }

    static void checkPosition(MissionItem item, Object at) {
        if (at instanceof Rel) {
            double[] ned = at.from.displacementTo(item.position())
            assert Math.abs(ned[0] - at.north) < 0.1
            assert Math.abs(ned[1] - at.east) < 0.1
        } else {
            assert [item.x(), item.y()] == at
        }
    }

    def "#command: item #seq is command #cmd"() {
        given:
        Mission mission = withPrefix(command)
        List<MissionItem> items = mission.items(null)
        MissionItem item = items[seq]

        expect: 'the item'
        checkPosition(item, at)
        item == new MissionItem(seq, cmd, frame, p1 as float, p2 as float, p3 as float, p4 as float, item.x(), item.y(),
                z as float, true)

        and: 'the mission around it: home placeholder, goPos A, consecutive seqs, declared count == emitted count'
        items[0] == new MissionItem(0, WAYPOINT, GLOBAL_INT, 0, 0, 0, 0, HOME7[0], HOME7[1], 820f, true)
        items[1] == new MissionItem(1, WAYPOINT, GLOBAL_INT, 0, 50, 0, NaN, A7[0], A7[1], 100f, true)
        items*.seq() == (0..<items.size()).toList()
        mission.missionPoints() == items.size()
        items.every { it.command() != DO_SET_HOME }

        where:
        command                                                    | seq || cmd                 | frame      | p1 | p2  | p3 | p4  | at                   | z
        // goPos (row 3)
        'goPos 41.184742, -8.704601'                               | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | B7                   | 0
        'goPos 41.184742, -8.704601, 150'                          | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | B7                   | 150
        'goPos B'                                                  | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | B7                   | 150
        // takeOff, takeOffWithYaw (rows 4, 5)
        'takeOff B'                                                | 2   || TAKEOFF             | GLOBAL_INT | 15 | 0   | 0  | NaN | B7                   | 150
        'takeOff B, 20'                                            | 2   || TAKEOFF             | GLOBAL_INT | 20 | 0   | 0  | NaN | B7                   | 150
        'takeOffWithYaw B, 20'                                     | 2   || TAKEOFF             | GLOBAL_INT | 20 | 0   | 0  | NaN | B7                   | 150
        'takeOffWithYaw B, 20, 90'                                 | 2   || TAKEOFF             | GLOBAL_INT | 20 | 0   | 0  | 90  | B7                   | 150
        // move, moveFromHome (rows 6, 7): from the last registered position (A) or from home
        'move 100, 200'                                            | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | fromA(100, 200)      | 100
        'move 100, 200, 30'                                        | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | fromA(100, 200)      | 130
        'move(-100, -200, -30)'                                    | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | fromA(-100, -200)    | 70
        'moveFromHome 100, 200, 30'                                | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | fromHome(100, 200)   | 850
        // moveAndLoiter* (rows 8 to 13)
        'moveAndLoiterPos 100, 200, 30'                            | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 15 | 0   | fromA(100, 200)      | 130
        'moveAndLoiterPos 100, 200, 30, 40'                        | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 40 | 0   | fromA(100, 200)      | 130
        'moveAndLoiterTurns 100, 200, 30'                          | 2   || LOITER_TURNS        | GLOBAL_INT | 10 | 0   | 15 | 0   | fromA(100, 200)      | 130
        'moveAndLoiterTurns 100, 200, 30, 3'                       | 2   || LOITER_TURNS        | GLOBAL_INT | 3  | 0   | 15 | 0   | fromA(100, 200)      | 130
        'moveAndLoiterTurns 100, 200, 30, 3, 40'                   | 2   || LOITER_TURNS        | GLOBAL_INT | 3  | 0   | 40 | 0   | fromA(100, 200)      | 130
        'moveAndLoiterTime 100, 200, 30, 60'                       | 2   || LOITER_TIME         | GLOBAL_INT | 60 | 0   | 15 | 0   | fromA(100, 200)      | 130
        'moveAndLoiterTime 100, 200, 30, 60, 40'                   | 2   || LOITER_TIME         | GLOBAL_INT | 60 | 0   | 40 | 0   | fromA(100, 200)      | 130
        'moveAndLoiterFromHome 100, 200, 30'                       | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 15 | 0   | fromHome(100, 200)   | 850
        'moveAndLoiterFromHome 100, 200, 30, 40'                   | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 40 | 0   | fromHome(100, 200)   | 850
        'moveAndLoiterTurnsFromHome 100, 200, 30'                  | 2   || LOITER_TURNS        | GLOBAL_INT | 10 | 0   | 15 | 0   | fromHome(100, 200)   | 850
        'moveAndLoiterTurnsFromHome 100, 200, 30, 3'               | 2   || LOITER_TURNS        | GLOBAL_INT | 3  | 0   | 15 | 0   | fromHome(100, 200)   | 850
        'moveAndLoiterTurnsFromHome 100, 200, 30, 3, 40'           | 2   || LOITER_TURNS        | GLOBAL_INT | 3  | 0   | 40 | 0   | fromHome(100, 200)   | 850
        'moveAndLoiterTimeFromHome 100, 200, 30, 60'               | 2   || LOITER_TIME         | GLOBAL_INT | 60 | 0   | 15 | 0   | fromHome(100, 200)   | 850
        'moveAndLoiterTimeFromHome 100, 200, 30, 60, 40'           | 2   || LOITER_TIME         | GLOBAL_INT | 60 | 0   | 40 | 0   | fromHome(100, 200)   | 850
        // loiterPos, loiterTurns, loiterTime (rows 14 to 16)
        'loiterPos B'                                              | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 15 | 0   | B7                   | 150
        'loiterPos B, 40'                                          | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 40 | 0   | B7                   | 150
        'loiterPos 41.184742, -8.704601, 150'                      | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 15 | 0   | B7                   | 150
        'loiterPos 41.184742, -8.704601, 150, 40'                  | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 40 | 0   | B7                   | 150
        'loiterTurns 41.184742, -8.704601, 150'                    | 2   || LOITER_TURNS        | GLOBAL_INT | 10 | 0   | 15 | 0   | B7                   | 150
        'loiterTurns 41.184742, -8.704601, 150, 3'                 | 2   || LOITER_TURNS        | GLOBAL_INT | 3  | 0   | 15 | 0   | B7                   | 150
        'loiterTurns 41.184742, -8.704601, 150, 3, 40'             | 2   || LOITER_TURNS        | GLOBAL_INT | 3  | 0   | 40 | 0   | B7                   | 150
        'loiterTime 41.184742, -8.704601, 150, 60'                 | 2   || LOITER_TIME         | GLOBAL_INT | 60 | 0   | 15 | 0   | B7                   | 150
        'loiterTime 41.184742, -8.704601, 150, 60, 40'             | 2   || LOITER_TIME         | GLOBAL_INT | 60 | 0   | 40 | 0   | B7                   | 150
        // landingPoint (row 17), both forms
        'landingPoint 41.184742, -8.704601'                        | 2   || LAND                | GLOBAL_INT | 0  | 0   | 0  | NaN | B7                   | 0
        'landingPoint 41.184742, -8.704601, 150'                   | 2   || LAND                | GLOBAL_INT | 0  | 0   | 0  | NaN | B7                   | 150
        'landingPoint 41.184742, -8.704601, 150, 90'               | 2   || LAND                | GLOBAL_INT | 0  | 0   | 0  | 90  | B7                   | 150
        'landingPoint 41.184742, -8.704601, 150, 90, 2'            | 2   || LAND                | GLOBAL_INT | 0  | 2   | 0  | 90  | B7                   | 150
        'landingPoint B'                                           | 2   || LAND                | GLOBAL_INT | 0  | 0   | 0  | NaN | B7                   | 150
        'landingPoint B, 90'                                       | 2   || LAND                | GLOBAL_INT | 0  | 0   | 0  | 90  | B7                   | 150
        'landingPoint B, 90, 1'                                    | 2   || LAND                | GLOBAL_INT | 0  | 1   | 0  | 90  | B7                   | 150
        // returnHome* (rows 18 to 20)
        // returnHome and returnHomeAndLoiter: over home at the last registered height (A's, 100 m)
        'returnHome()'                                             | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | HOME7                | 100
        'returnHomeAndLoiter()'                                    | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 15 | 0   | HOME7                | 100
        'returnHomeAndLoiter 40'                                   | 2   || LOITER_UNLIM        | GLOBAL_INT | 0  | 0   | 40 | 0   | HOME7                | 100
        'returnHomeAndLand()'                                      | 2   || LAND                | GLOBAL_INT | 0  | 0   | 0  | NaN | HOME7                | 820
        'returnHomeAndLand 90'                                     | 2   || LAND                | GLOBAL_INT | 0  | 0   | 0  | 90  | HOME7                | 820
        'returnHomeAndLand 90, 2'                                  | 2   || LAND                | GLOBAL_INT | 0  | 2   | 0  | 90  | HOME7                | 820
        // speed (row 21; F-8: default type 0 = airspeed, throttle -1 = unchanged)
        'speed 12'                                                 | 2   || DO_CHANGE_SPEED     | MISSION    | 0  | 12  | -1 | 0   | NONE                 | 0
        'speed 12, 1'                                              | 2   || DO_CHANGE_SPEED     | MISSION    | 1  | 12  | -1 | 0   | NONE                 | 0
        // altitude (row 22; design §5: a waypoint at the last registered position, at the new height)
        'altitude 300'                                             | 2   || WAYPOINT            | GLOBAL_INT | 0  | 50  | 0  | NaN | A7                   | 300
        // delay (row 23; F-10: p1 = seconds, no time of day)
        'delay 30'                                                 | 2   || NAV_DELAY           | MISSION    | 30 | -1  | -1 | -1  | NONE                 | 0
        // surveyArea (rows 24, 25): seq 3 is the first shift, one leg (length + 25 m) and one spacing from the base
        'surveyArea 1000, 400'                                     | 3   || WAYPOINT            | GLOBAL_INT | 0  | 25  | 0  | NaN | fromA(1025, -50)     | 100
        'surveyArea 1000, 400, 100'                                | 3   || WAYPOINT            | GLOBAL_INT | 0  | 25  | 0  | NaN | fromA(1025, -100)    | 100
        'surveyArea 1000, 400, 100, "SOUTH_EAST"'                  | 3   || WAYPOINT            | GLOBAL_INT | 0  | 25  | 0  | NaN | fromA(-1025, 100)    | 100
        'surveyArea 1000, 400, "NORTH_EAST"'                       | 3   || WAYPOINT            | GLOBAL_INT | 0  | 25  | 0  | NaN | fromA(1025, 50)      | 100
        'surveyArea B, 1000, 400'                                  | 3   || WAYPOINT            | GLOBAL_INT | 0  | 25  | 0  | NaN | fromB(1025, -50)     | 150
        'surveyArea B, 1000, 400, 100'                             | 3   || WAYPOINT            | GLOBAL_INT | 0  | 25  | 0  | NaN | fromB(1025, -100)    | 150
        'surveyArea B, 1000, 400, 100, "SOUTH_WEST"'               | 3   || WAYPOINT            | GLOBAL_INT | 0  | 25  | 0  | NaN | fromB(-1025, -100)   | 150
        'surveyArea B, 1000, 400, "SOUTH_EAST"'                    | 3   || WAYPOINT            | GLOBAL_INT | 0  | 25  | 0  | NaN | fromB(-1025, 50)     | 150
        // camera (rows 26 to 29; F-10: p2 = interval, p3 = count)
        'capturePhoto()'                                           | 2   || IMAGE_START_CAPTURE | MISSION    | 0  | 0   | 1  | 0   | NONE                 | 0
        'captureSeveralPhotos 5'                                   | 2   || IMAGE_START_CAPTURE | MISSION    | 0  | 2   | 5  | 0   | NONE                 | 0
        'captureSeveralPhotos 5, 3'                                | 2   || IMAGE_START_CAPTURE | MISSION    | 0  | 3   | 5  | 0   | NONE                 | 0
        'captureUntilStop()'                                       | 2   || IMAGE_START_CAPTURE | MISSION    | 0  | 2   | 0  | 0   | NONE                 | 0
        'captureUntilStop 3'                                       | 2   || IMAGE_START_CAPTURE | MISSION    | 0  | 3   | 0  | 0   | NONE                 | 0
        'stopCapturing()'                                          | 2   || IMAGE_STOP_CAPTURE  | MISSION    | 0  | 0   | 0  | 0   | NONE                 | 0
    }

    def "surveyArea emits 2N items: N passes of length + 25 m, N - 1 shifts, back to base (#width / #spacing)"() {
        given:
        Mission m = withPrefix { surveyArea 1000, width, spacing, 'NORTH_EAST' }
        List<MissionItem> survey = m.items(null).drop(2)

        expect:
        survey.size() == 2 * passes
        m.missionPoints() == 2 + 2 * passes
        survey*.seq() == (2..<(2 + 2 * passes)).toList()
        survey.last().x() == A7[0] && survey.last().y() == A7[1]
        survey.every { it.z() == 100f && it.command() == WAYPOINT && it.param2() == 25f }

        where: 'N = round(W / S) + 1 (F-4; the reference worked numbers of C.8)'
        width | spacing || passes
        10000 | 500     || 21
        1000  | 100     || 11
        1000  | 200     || 6
        100   | 50      || 3
        125   | 50      || 4     // 2.5 rounds half up
        0     | 50      || 1
    }

    def "home (#form) is item 0 and emits no DO_SET_HOME item; the mission keeps it"() {
        when:
        Mission m = missionOf {
            home.call(delegate)
            allowBelowHome true
            goPos 41.185781, -8.70606486, 100
        }
        List<MissionItem> items = m.items(null)

        then:
        items.size() == 2
        items[0] == new MissionItem(0, WAYPOINT, GLOBAL_INT, 0, 0, 0, 0, HOME7[0], HOME7[1], z as float, true)
        items[1].command() == WAYPOINT
        Math.abs(m.home.latitudeDegrees() - 40.444233d) < 1e-9
        m.home.hae() == z
        m.commandList.size() == 1

        where:
        form              | home                                                     || z
        'lat, lon'        | { b -> b.home(40.444233, -7.375234) }                    || 0
        'lat, lon, hae'   | { b -> b.home(40.444233, -7.375234, 820) }               || 820
        'position'        | { b -> b.home(Position.fromDegrees(40.444233, -7.375234, 820)) } || 820
    }

    def "without home, item 0 is the vehicle's home, else the first absolute position (design §5)"() {
        given:
        Mission m = missionOf {
            speed 10
            takeOff B
            goPos 41.185781, -8.70606486, 100
        }

        expect:
        m.home == null
        m.items(null)[0] == new MissionItem(0, WAYPOINT, GLOBAL_INT, 0, 0, 0, 0, B7[0], B7[1], 150f, true)
        m.items(HOME)[0] == new MissionItem(0, WAYPOINT, GLOBAL_INT, 0, 0, 0, 0, HOME7[0], HOME7[1], 820f, true)
        m.items(HOME)*.command() == [WAYPOINT, DO_CHANGE_SPEED, TAKEOFF, WAYPOINT]
    }

    def "name sets the task id; the default is MissionPlan_line<N>, N the line of the mission word"() {
        when:
        Mission named = missionOf {
            name 'Survey Area'
            goPos 41.185781, -8.70606486, 100
        }
        String spec = MissionCommandsSpec.name
        int line = new Throwable().stackTrace.find { it.className == spec }.lineNumber + 1
        Mission unnamed = MissionDsl.mission { goPos 41.185781, -8.70606486, 100 }.mission()

        then:
        named.id == 'Survey Area'
        unnamed.id == "MissionPlan_line${line}"
    }

    def "jumpToItem is a ground-side jump: no item, keyed by the seq of the item before it (F-20)"() {
        given:
        Mission m = missionOf {
            home HOME
            allowBelowHome true
            takeOff B
            move 100, 0, 10
            jumpToItem 2, 3
            move 0, 100
            jumpToItem 1
        }
        List<JumpToItem> jumps = m.commandList.findAll { it instanceof JumpToItem } as List<JumpToItem>

        expect:
        m.items(null)*.command() == [WAYPOINT, TAKEOFF, WAYPOINT, WAYPOINT]
        jumps*.item() == [2, 1]
        jumps*.repetitions() == [3, 1]
        m.nonMissionCommands() == [2: [jumps[0]], 3: [jumps[1]]]
    }

    def "position tracking (C.6.1, F-9): after #before, a relative move starts from item #reference"() {
        given:
        Closure row = (Closure) SHELL.evaluate("return { -> ${before} }")
        Mission m = missionOf {
            allowBelowHome true
            row.delegate = delegate
            row.resolveStrategy = Closure.DELEGATE_FIRST
            row.call()
            move 0, 100, 10
        }
        List<MissionItem> items = m.items(null)
        MissionItem moved = items.last()
        MissionItem from = items[reference]
        double[] ned = from.position().displacementTo(moved.position())

        expect:
        Math.abs(ned[0]) < 0.1
        Math.abs(ned[1] - 100) < 0.1
        moved.z() == from.z() + 10f

        where:
        before                                                                              || reference
        'home HOME'                                                                           || 0
        'home HOME; takeOff B'                                                                || 1
        'home HOME; loiterPos B'                                                              || 0
        'home HOME; loiterTurns 41.184742, -8.704601, 150; loiterTime 41.184742, -8.704601, 150, 5'|| 0
        'home HOME; landingPoint B'                                                           || 0
        'goPos B'                                                                             || 0
        'home HOME; goPos B'                                                                  || 1
        'goPos B; home HOME'                                                                  || 1
        'home HOME; goPos B; takeOff A; loiterPos A; landingPoint A'                          || 2
        'home HOME; goPos B; speed 5; delay 3; capturePhoto(); stopCapturing()'               || 1
        'home HOME; goPos B; move 10, 20, 5'                                                  || 2
        'home HOME; goPos B; moveFromHome 10, 20, 5'                                          || 2
        'home HOME; goPos B; moveAndLoiterTurns 10, 20, 5'                                    || 2
        'home HOME; goPos B; moveAndLoiterTimeFromHome 10, 20, 5, 30'                         || 2
        'home HOME; goPos B; altitude 300'                                                    || 2
        'home HOME; goPos B; returnHome()'                                                    || 2
        'home HOME; goPos B; returnHomeAndLoiter()'                                           || 2
        'home HOME; goPos B; returnHomeAndLand()'                                             || 2
        'home HOME; goPos B; surveyArea 300, 100'                                             || 1
        'home HOME; goPos A; surveyArea B, 300, 100'                                          || 7   // the base: the survey's last item
    }

    def "altitude registers its position: a later move starts from it, at the new height"() {
        given:
        Mission m = missionOf {
            home HOME
            allowBelowHome true
            goPos B
            altitude 400
            move 0, 0, 10
        }
        List<MissionItem> items = m.items(null)

        expect:
        items[2].x() == B7[0] && items[2].y() == B7[1] && items[2].z() == 400f
        items[3].x() == B7[0] && items[3].y() == B7[1] && items[3].z() == 410f
    }
}
