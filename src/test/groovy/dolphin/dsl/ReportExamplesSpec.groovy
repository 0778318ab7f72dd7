package dolphin.dsl

import dolphin.core.NodeSet
import dolphin.core.Position
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR
import static dolphin.dsl.ScriptResult.Outcome.STOPPED

/**
 * The report's task grammar (Figure 2) and the shapes of Listings 1 to 4, with the test platform's
 * {@code fly} tasks in place of IMC plans and MAVLink missions.
 */
class ReportExamplesSpec extends Specification {

    def "Figure 2: #production"() {
        given:
        def h = new ScriptHarness(2)

        when:
        def r = h.run("""
            v1 = pick { }
            v2 = pick { }
            t = ${task}
            execute t
        """)

        then:
        r.outcome == COMPLETED
        h.platform.journal*.toString() == journal
        h.now() == end

        where:
        production               | task                                                                                        || journal                                                                              | end
        'PlatformTask'           | "fly('a', 1)"                                                                               || ['start a 1 @0.0', 'done a 1 @1.0']                                                  | 1.0d
        "action '{' Code '}'"    | "action { post done: 1 }"                                                                   || []                                                                                   | 0.0d
        "condition '{' Cond '}'" | "condition { true }"                                                                        || []                                                                                   | 0.0d
        "Task '>>' Task"         | "fly('a', 1) >> fly('b', 1)"                                                                || ['start a 1 @0.0', 'done a 1 @1.0', 'start b 1 @1.0', 'done b 1 @2.0']               | 2.0d
        "Task '|' Task"          | "fly('a', 1) | fly('b', 2)"                                                                 || ['start a 1 @0.0', 'start b 2 @0.0', 'done a 1 @1.0', 'done b 2 @2.0']               | 2.0d
        "Task '[' VSet ']'"      | "fly('a', 1)[v2]"                                                                           || ['start a 2 @0.0', 'done a 2 @1.0']                                                  | 1.0d
        "allOf '{' WhenThen+ '}'"| "allOf { when { true } then fly('a', 1); when { true } then fly('b', 1) }"                  || ['start a 1 @0.0', 'done a 1 @1.0', 'start b 1 @1.1', 'done b 1 @2.1']               | 2.1d
        "oneOf '{' WhenThen+ '}'"| "oneOf { when { false } then fly('a', 1); when { true } then fly('b', 1) }"                 || ['start b 1 @0.0', 'done b 1 @1.0']                                                  | 1.0d
        "waitFor {Cond} then Task" | "waitFor { true } then fly('a', 1)"                                                       || ['start a 1 @0.0', 'done a 1 @1.0']                                                  | 1.0d
        "until {Cond} run Task"  | "until { false } run fly('a', 1)"                                                           || ['start a 1 @0.0', 'done a 1 @1.0']                                                  | 1.0d
        'idle Time'              | "idle 1.5"                                                                                  || []                                                                                   | 1.5d
        'during Time run Task'   | "during 1 run fly('a', 5)"                                                                  || ['start a 1 @0.0', 'stop a 1 @1.0']                                                  | 1.0d
        "watch Task onError {Code}" | "watch failing('a', 1, 'x') onError { ignore() }"                                        || ['start a 1 @0.0', 'error a 1 @1.0']                                                 | 1.0d
    }

    def "Listing 1's shape: three UUVs with a sidescan in a 2 km area run three surveys concurrently"() {
        given:
        def h = new ScriptHarness(0)
        def comporta = Position.fromDegrees(38.435, -8.861, 0)
        h.platform.addNode('1', 'UUV', comporta, ['Sidescan'])
        h.platform.addNode('2', 'UAV', comporta, ['Sidescan'])                                  // wrong type
        h.platform.addNode('3', 'UUV', comporta, [])                                            // no sidescan
        h.platform.addNode('4', 'UUV', Position.fromDegrees(38.7, -9.1, 0), ['Sidescan'])        // far away
        h.platform.addNode('5', 'UUV', comporta.displace(500, 500, 0), ['Sidescan'])
        h.platform.addNode('6', 'UUV', comporta.displace(-800, 0, 0), ['Sidescan', 'Camera'])

        when:
        def r = h.run('''
            // Define area of operation.
            Comporta = (location 38.43462, -8.86118) ^ 2.km

            // Select UUVs
            UUVs = pick {
                count 3
                type 'UUV'
                region Comporta
                payload 'Sidescan'
            }

            // Set connection timeout.
            setConnectionTimeout 10.minutes

            // Execute ocean surveys
            execute UUVs:
                fly('survey1', 100) |
                fly('survey2', 120) |
                fly('survey3', 90)

            // End!
            message 'Done!'
        ''')

        then:
        r.outcome == COMPLETED
        (h.engine.variable('UUVs') as NodeSet).ids() == ['1', '5', '6']
        h.platform.entries('start').collect { "${it.task} ${it.node} @${it.time}" } ==
                ['survey1 1 @0.0', 'survey2 5 @0.0', 'survey3 6 @0.0']
        h.platform.entries('done')*.time.max() == 120.0d
        h.messages.last() == 'Done!'
        h.engine.environment.defaultConnectionTimeout == 600d
        ['1', '5', '6'].every { h.platform.node(it).connectionTimeout == 600d }
    }

    def "Listing 2's pattern: wait for a charged battery, run until it is low, then return"() {
        given:
        def h = new ScriptHarness(2)
        def uav = h.platform.node('1')
        uav.battery = 0.5
        h.at(10) { uav.battery = 0.95 }
        h.at(50) { uav.battery = 0.25 }

        when:
        def r = h.run('''
            simpleMission = fly('simpleMission', 1000)
            returnHome = fly('returnHome', 20)
            v1 = pick {
                type 'UAV'
                timeout 30.seconds
            }
            execute v1: waitFor {battery(v1) >= 0.9} then ((simpleMission / {battery(v1) < 0.3}) >> returnHome)
            //Release the drone for other possible tasks
            release v1
            again = pick { }
        ''')

        then:
        r.outcome == COMPLETED
        h.platform.journal*.toString() == ['start simpleMission 1 @10.0', 'stop simpleMission 1 @50.0',
                                           'start returnHome 1 @50.0', 'done returnHome 1 @70.0']
        (h.engine.variable('again') as NodeSet).ids() == ['1']
    }

    def "Listing 2 with its endless loop runs cycle after cycle until the engine is stopped"() {
        given:
        def h = new ScriptHarness(1)
        def uav = h.platform.node('1')
        uav.battery = 0.5
        h.at(10) { uav.battery = 0.95 }
        h.at(50) { uav.battery = 0.25 }
        h.at(100) { uav.battery = 0.95 }
        h.at(130) { h.engine.stop() }

        when:
        def r = h.run('''
            simpleMission = fly('simpleMission', 1000)
            returnHome = fly('returnHome', 20)
            //Execute the task
            while (true) {
                v1 = pick {
                    type 'UAV'
                    timeout 30.seconds
                }
                execute v1: waitFor {battery(v1) >= 0.9} then ((simpleMission / {battery(v1) < 0.3}) >> returnHome)
                //Release the drone for other possible tasks
                release v1
            }
        ''')

        then:
        r.outcome == STOPPED
        h.platform.journal*.toString() == ['start simpleMission 1 @10.0', 'stop simpleMission 1 @50.0',
                                           'start returnHome 1 @50.0', 'done returnHome 1 @70.0',
                                           'start simpleMission 1 @100.0', 'stop simpleMission 1 @130.0']
        uav.releases == ['1']
    }

    def "Listing 2 as printed, with 'then' on the next line, is a script error at the 'then' line, found before running"() {
        given:
        def h = new ScriptHarness(1)

        when:
        def source = '''v1 = pick {
    type 'UAV'
    timeout 30.seconds
}
execute v1:
    waitFor {battery(v1) >= 0.9}
      then ((fly('m', 100) / {battery(v1) < 0.3})
         >> fly('r', 10))
release v1
'''
        def checked = h.engine.check(source, 'listing2.dolphin')
        def r = h.run(source, 'listing2.dolphin')

        then:
        checked == [r.error]
        r.outcome == SCRIPT_ERROR
        r.error.file == 'listing2.dolphin'
        r.error.line == 7
        r.error.message.contains("'then' begins a new statement")
        r.error.message.contains("Expected 'then' on the same line")
        h.messages.every { !it.startsWith('picked') }
    }

    def "Listing 3's shape: two vehicles, independent surveys, one shared return task that both run (E-3)"() {
        given:
        def h = new ScriptHarness(2)
        def a = h.platform.node('1')
        def b = h.platform.node('2')
        a.battery = 0.95
        b.battery = 0.5
        h.at(5) { b.battery = 0.95 }
        h.at(40) { a.battery = 0.25 }
        h.at(65) { b.battery = 0.25 }

        when:
        def r = h.run('''
            surveyNorth = fly('surveyNorth', 1000)
            surveySouth = fly('surveySouth', 1000)
            returnHome = fly('returnHome', 20)
            v1 = pick {
                type 'UAV'
                timeout 30.seconds
            }
            v2 = pick {
                type 'UAV'
                timeout 30.seconds
            }
            execute v1: waitFor {battery(v1) >= 0.9} then ((surveyNorth / {battery(v1) < 0.3}) >> returnHome),
                    v2: waitFor {battery(v2) >= 0.9} then ((surveySouth / {battery(v2) < 0.3}) >> returnHome)
            release v1 + v2
            message 'both back'
        ''')

        then:
        r.outcome == COMPLETED
        h.platform.journal*.toString() == ['start surveyNorth 1 @0.0', 'start surveySouth 2 @5.0',
                                           'stop surveyNorth 1 @40.0', 'start returnHome 1 @40.0',
                                           'done returnHome 1 @60.0',
                                           'stop surveySouth 2 @65.0', 'start returnHome 2 @65.0',
                                           'done returnHome 2 @85.0']
        h.messages.last() == 'both back'
        h.now() == 85.0d
        a.releases.isEmpty() && b.releases.isEmpty()     // released by the script, so nothing is called on them
    }

    def "Listing 4 as printed ('execute' alone on its line) is a script error found before running"() {
        given:
        def h = new ScriptHarness(2)
        def source = '''v1 = pick { type 'UAV'; timeout 30.seconds }
v2 = pick { type 'UAV'; timeout 30.seconds }
//Execute the task
while (true) {
      execute
      v1:
       waitFor {battery(v1) >= 0.9}
        then ((fly('n', 10) /
         {battery(v1) < 0.3})
         >> fly('r', 5)),
      v2:
       waitFor {battery(v2) >= 0.9}
        then ((fly('s', 10) /
                 {battery(v2) < 0.3})
         >> fly('r', 5))
}
'''

        when:
        def checked = h.engine.check(source, 'listing4.dolphin')
        def r = h.run(source, 'listing4.dolphin')

        then:
        checked.size() == 1
        checked[0].file == 'listing4.dolphin'
        checked[0].line == 5
        checked[0].message.contains("'execute' stands alone on its line")
        checked[0].message.contains("the 'v1:' entry on the next line is not its argument")
        r.outcome == SCRIPT_ERROR
        r.error == checked[0]
        h.messages.every { !it.startsWith('picked') }
    }

    def "Listing 4 laid out correctly keeps two vehicles in the air, swapping in charged ones each cycle"() {
        given:
        def h = new ScriptHarness(4)
        def node = { String id -> h.platform.node(id) }
        (1..4).each { node(String.valueOf(it)).battery = 0.95 }
        h.at(40) { node('1').battery = 0.25 }
        h.at(60) { node('2').battery = 0.25 }
        h.at(100) { node('3').battery = 0.25 }
        h.at(110) { node('4').battery = 0.25 }
        h.at(150) { h.engine.stop() }

        when:
        def r = h.run('''
            surveyNorth = fly('surveyNorth', 1000)
            surveySouth = fly('surveySouth', 1000)
            returnHome = fly('returnHome', 20)
            v1 = pick { type 'UAV'; timeout 30.seconds }
            v2 = pick { type 'UAV'; timeout 30.seconds }
            while (true) {
                execute v1: waitFor {battery(v1) >= 0.9} then ((surveyNorth / {battery(v1) < 0.3}) >> returnHome),
                        v2: waitFor {battery(v2) >= 0.9} then ((surveySouth / {battery(v2) < 0.3}) >> returnHome)
                v1Temp = pick { type 'UAV'; timeout 30.seconds }
                v2Temp = pick { type 'UAV'; timeout 30.seconds }
                release v1 + v2
                v1 = v1Temp
                v2 = v2Temp
            }
        ''')

        then:
        r.outcome == STOPPED
        h.platform.entries('start').collect { "${it.task} ${it.node} @${it.time}" } ==
                ['surveyNorth 1 @0.0', 'surveySouth 2 @0.0', 'returnHome 1 @40.0', 'returnHome 2 @60.0',
                 'surveyNorth 3 @80.0', 'surveySouth 4 @80.0', 'returnHome 3 @100.0', 'returnHome 4 @110.0']
        h.platform.entries('done').collect { "${it.task} ${it.node} @${it.time}" } ==
                ['returnHome 1 @60.0', 'returnHome 2 @80.0', 'returnHome 3 @120.0', 'returnHome 4 @130.0']
        // the third cycle waits for vehicles 1 and 2 to charge; stopping releases them
        node('1').releases == ['1']
        node('2').releases == ['2']
        node('3').releases.isEmpty()
        node('4').releases.isEmpty()
    }
}
