package dolphin.dsl

import dolphin.core.ManualClock
import dolphin.core.NodeSet
import dolphin.core.Position
import dolphin.testing.ScriptHarness
import dolphin.testing.TestPlatform
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.HALTED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/** {@code pick { ... }} and each of its clauses (reference A.2 "pick"). */
class PickSpec extends Specification {

    static final Position APDL = Position.fromDegrees(41.185781, -8.70606486, 0)
    static final Position B1 = Position.fromDegrees(41.184742, -8.704601, 0)   // 168.5 m from APDL

    ScriptHarness h = new ScriptHarness(0)

    private List<String> ids(String variable) {
        def set = h.engine.variable(variable)
        assert set instanceof NodeSet
        ((NodeSet) set).ids()
    }

    def "pick without clauses binds one vehicle, the first in platform order, and says so"() {
        given:
        3.times { h.platform.addNode(String.valueOf(it + 1)) }

        when:
        def r = h.run('v = pick { }')

        then:
        r.outcome == COMPLETED
        ids('v') == ['1']
        h.messages.contains('picked { 1 } from the free vehicles { 1 2 3 }')
    }

    def "count n binds n distinct vehicles in platform order"() {
        given:
        4.times { h.platform.addNode(String.valueOf(it + 1)) }

        when:
        h.run('v = pick { count 3 }')

        then:
        ids('v') == ['1', '2', '3']
    }

    def "a vehicle bound by an earlier pick is not picked again"() {
        given:
        3.times { h.platform.addNode(String.valueOf(it + 1)) }

        when:
        h.run('''
            a = pick { }
            b = pick { count 2 }
        ''')

        then:
        ids('a') == ['1']
        ids('b') == ['2', '3']
    }

    def "count larger than the free vehicles halts the script"() {
        given:
        2.times { h.platform.addNode(String.valueOf(it + 1)) }

        when:
        def r = h.run('''
            v = pick { count 3 }
            message 'not reached'
        ''')

        then:
        r.outcome == HALTED
        r.message.contains('3 free vehicle(s)')
        !h.messages.contains('not reached')
    }

    def "type matches the node type exactly"() {
        given:
        h.platform.addNode('1', 'UAV')
        h.platform.addNode('2', 'UUV')
        h.platform.addNode('3', 'UUV')
        h.platform.addNode('4', 'uuv')

        when:
        h.run('''
            a = pick { type 'UUV' }
            b = pick { type 'UUV' }
            c = pick { type 'uuv' }
        ''')

        then:
        ids('a') == ['2']
        ids('b') == ['3']
        ids('c') == ['4']
    }

    def "id matches the node id exactly, also when written as a number"() {
        given:
        3.times { h.platform.addNode(String.valueOf(it + 1)) }

        when:
        h.run('''
            a = pick { id '3' }
            b = pick { id 2 }
        ''')

        then:
        ids('a') == ['3']
        ids('b') == ['2']
    }

    def "id of a vehicle that is not there halts"() {
        given:
        h.platform.addNode('1')

        expect:
        h.run("v = pick { id '7' }").outcome == HALTED
    }

    def "payload requires every named component"() {
        given:
        h.platform.addNode('1', 'UUV', APDL, [])
        h.platform.addNode('2', 'UUV', APDL, ['Camera'])
        h.platform.addNode('3', 'UUV', APDL, ['Camera', 'Sidescan'])

        when:
        h.run('''
            both = pick { payload 'Sidescan', 'Camera' }
            cam = pick { payload 'Camera' }
        ''')

        then:
        ids('both') == ['3']
        ids('cam') == ['2']
    }

    def "region with an area keeps vehicles inside the area"() {
        given:
        h.platform.addNode('1', 'UAV', APDL)
        h.platform.addNode('2', 'UAV', B1)

        when:
        h.run('''
            zone = (location 41.184742, -8.704601) ^ 50
            v = pick { region zone }
        ''')

        then:
        ids('v') == ['2']
    }

    def "region with a centre and a radius measures the straight-line distance"() {
        given:
        h.platform.addNode('1', 'UAV', B1)
        h.platform.addNode('2', 'UAV', APDL)

        when:
        h.run("""
            near = pick { region location(41.185781, -8.70606486), ${radius} }
        """)

        then:
        ids('near') == expected

        where:
        radius || expected
        160    || ['2']          // B1 is 168.5 m away
        170    || ['1']          // both inside: platform order
    }

    def "heights count: a vehicle 1000 m above the centre is not within 100 m"() {
        given:
        h.platform.addNode('1', 'UAV', Position.fromDegrees(41.185781, -8.70606486, 1000))
        h.platform.addNode('2', 'UAV', APDL)

        when:
        h.run('''
            low = pick { region location(41.185781, -8.70606486), 100 }
            high = pick { region location(41.185781, -8.70606486, 1000), 100 }
        ''')

        then:
        ids('low') == ['2']
        ids('high') == ['1']
    }

    def "a vehicle that has not reported a position is outside every region"() {
        given:
        h.platform.addNode('1', 'UAV', null)

        expect:
        h.run('v = pick { region location(41.185781, -8.70606486), 1000000 }').outcome == HALTED
    }

    def "clauses combine: every filter must match"() {
        given:
        h.platform.addNode('1', 'UUV', APDL, ['Sidescan'])      // right type, wrong place
            .position = Position.fromDegrees(40, -8, 0)
        h.platform.addNode('2', 'UAV', APDL, ['Sidescan'])      // wrong type
        h.platform.addNode('3', 'UUV', APDL, [])                // no sidescan
        h.platform.addNode('4', 'UUV', APDL, ['Sidescan'])      // all three

        when:
        h.run('''
            v = pick {
                type 'UUV'
                payload 'Sidescan'
                region location(41.185781, -8.70606486), 500
            }
        ''')

        then:
        ids('v') == ['4']
    }

    def "a repeated clause replaces the earlier one"() {
        given:
        h.platform.addNode('1', 'UUV')
        h.platform.addNode('2', 'UAV')

        when:
        h.run("v = pick { type 'UUV'; type 'UAV' }")

        then:
        ids('v') == ['2']
    }

    def "a vehicle that lost its link cannot be picked"() {
        given:
        h.platform.addNode('1').connected = false
        h.platform.addNode('2')

        when:
        h.run('v = pick { }')

        then:
        ids('v') == ['2']
    }

    def "a picked vehicle gets the current connection timeout; setConnectionTimeout sets those held, not those released"() {
        given:
        h.platform.addNode('1')
        h.platform.addNode('2')

        when:
        h.run('''
            a = pick { }
            setConnectionTimeout 60
            b = pick { }
            release a
            setConnectionTimeout 90
        ''')

        then:
        h.platform.node('1').connectionTimeout == 60d
        h.platform.node('2').connectionTimeout == 90d
    }

    def "timeout #timeout: attempts every #pause s, so a vehicle connected at #connectAt s is picked at #pickedAt s"() {
        given:
        h.platform.addNode('1').connected = false
        h.at(connectAt) { h.platform.node('1').connected = true }

        when:
        def r = h.run("""
            v = pick { timeout ${timeout} }
            execute fly('probe', 1)
        """)

        then:
        r.outcome == COMPLETED
        h.platform.entries('start')*.time == [pickedAt]

        where:
        timeout | pause | connectAt || pickedAt
        5       | 1     | 0.5       || 1.0d      // max(1 s, 0.5 s)
        10      | 1     | 2.5       || 3.0d
        7       | 1     | 6.5       || 7.0d      // the attempt at the timeout itself still counts
        30      | 3     | 4         || 6.0d
        50      | 5     | 12        || 15.0d
        25      | 2.5   | 20.1      || 22.5d
    }

    def "a pick that finds nothing within timeout #timeout ends the run as HALTED at #timeout s"() {
        given:
        h.platform.addNode('1', 'UAV')
        h.at(timeout + 0.5) { h.platform.addNode('2', 'UUV') }   // too late

        when:
        def r = h.run("""
            v = pick { count 2; type 'UUV'; timeout ${timeout} }
            message 'not reached'
        """)

        then:
        r.outcome == HALTED
        r.exitCode() == 1
        h.now() == timeout as double
        r.message.contains('2 free vehicle(s)')
        r.message.contains('type UUV')
        r.message.contains("within ${timeout as double} s")
        h.messages.any { it.startsWith('halted: pick: could not find 2') }
        !h.messages.contains('not reached')

        where:
        timeout << [0, 5, 25]
    }

    def "with timeout #timeout the attempts are made at #attempts s"() {
        given: 'a platform that notes the virtual time of every look at its vehicles'
        def clock = ManualClock.autoAdvancing()
        List<Double> looks = new java.util.concurrent.CopyOnWriteArrayList()
        def platform = new TestPlatform() {
            @Override
            NodeSet getConnectedNodes() {
                looks << clock.seconds()
                super.getConnectedNodes()
            }
        }
        platform.addNode('1', 'UAV')
        def engine = new Engine(platform, clock)

        when:
        def r = engine.run("v = pick { type 'UUV'; timeout ${timeout} }", 'pick.dolphin').await(java.time.Duration.ofSeconds(20))

        then:
        r.outcome == HALTED
        looks.unique() == attempts      // (the halt message looks once more, at the end)
        clock.seconds() == attempts.last()

        where:
        timeout || attempts
        0       || [0.0d]
        3.5     || [0.0d, 1.0d, 2.0d, 3.0d, 4.0d]
        10      || (0..10).collect { it as double }
        30      || (0..10).collect { it * 3.0d }
    }

    def "a failed pick releases the vehicles picked before it"() {
        given:
        h.platform.addNode('1', 'UAV')

        when:
        def r = h.run('''
            a = pick { type 'UAV' }
            b = pick { type 'UUV' }
        ''')

        then:
        r.outcome == HALTED
        h.platform.node('1').releases == ['1']
    }

    def "count #count is a script error at the line of the clause"() {
        given:
        h.platform.addNode('1')

        when:
        def r = h.run("""v = pick {
            type 'UAV'
            count(${count})
        }""")

        then:
        r.outcome == SCRIPT_ERROR
        r.error.file == 'test.dolphin'
        r.error.line == 3
        r.error.message.contains("count must be positive, got ${count}")

        where:
        count << [0, -2]
    }

    def "a negative timeout is a script error at the line of the clause"() {
        given:
        h.platform.addNode('1')

        when:
        def r = h.run('''v = pick {
            timeout(-1)
        }''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 2
        r.error.message.contains('timeout must not be negative, got -1')
    }

    def "pick takes a number of seconds written with units"() {
        given:
        h.platform.addNode('1').connected = false
        h.at(65) { h.platform.node('1').connected = true }

        when:
        def r = h.run('''
            v = pick { timeout 2.minutes }
            execute fly('probe', 1)
        ''')

        then:
        r.outcome == COMPLETED
        h.platform.entries('start')*.time == [72.0d]    // attempts every 12 s
    }
}
