package dolphin.dsl

import dolphin.core.Area
import dolphin.core.Condition
import dolphin.core.ConcurrentTask
import dolphin.core.ConstrainedTask
import dolphin.core.NodeSet
import dolphin.core.Position
import dolphin.core.ResourceExplicitTask
import dolphin.core.SequentialTask
import dolphin.testing.FlyTask
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR
import static dolphin.dsl.ScriptResult.Outcome.TASK_ERROR

/** {@code T1 >> T2}, {@code T1 | T2} and {@code T[vset]} (reference A.2, A.4). */
class TaskOperatorsSpec extends Specification {

    ScriptHarness h = new ScriptHarness(3)

    private List<String> journal() { h.platform.journal*.toString() }

    def ">> starts the second task in the tick the first is DONE, and may reuse its vehicle"() {
        when:
        def r = h.run('''
            v = pick { }
            execute fly('a', 2.5) >> fly('b', 1) >> fly('c', 1)
        ''')

        then:
        r.outcome == COMPLETED
        journal() == ['start a 1 @0.0', 'done a 1 @2.5', 'start b 1 @2.5', 'done b 1 @3.5', 'start c 1 @3.5', 'done c 1 @4.5']
    }

    def ">> does not start the second task after an ERROR"() {
        when:
        def r = h.run('''
            v = pick { }
            execute failing('f', 2, 'boom') >> fly('b', 1)
        ''')

        then:
        r.outcome == TASK_ERROR
        journal() == ['start f 1 @0.0', 'error f 1 @2.0']
    }

    def "| runs both at once on distinct vehicles and is DONE when both are"() {
        when:
        def r = h.run('''
            v = pick { count 2 }
            execute fly('a', 5) | fly('b', 2)
            execute fly('next', 1)
        ''')

        then:
        r.outcome == COMPLETED
        journal() == ['start a 1 @0.0', 'start b 2 @0.0', 'done b 2 @2.0', 'done a 1 @5.0', 'start next 1 @5.0', 'done next 1 @6.0']
    }

    def "an ERROR in one branch of | stops the other at that moment"() {
        when:
        def r = h.run('''
            v = pick { count 2 }
            execute fly('a', 100) | failing('f', 3, 'boom')
        ''')

        then:
        r.outcome == TASK_ERROR
        journal() == ['start a 1 @0.0', 'start f 2 @0.0', 'error f 2 @3.0', 'stop a 1 @3.0']
    }

    def "| needs as many vehicles as branches"() {
        when:
        def r = h.run('''
            v = pick { count 2 }
            execute fly('a', 1) | fly('b', 1) | fly('c', 1)
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.message.contains('no vehicles to run task')
        journal().isEmpty()
    }

    def "T[v] allocates only from v"() {
        when:
        h.run('''
            v1 = pick { }
            v2 = pick { }
            v3 = pick { }
            execute fly('a', 1)[v3] | fly('b', 1)[v2 + v3]
        ''')

        then:
        journal().findAll { it.startsWith('start') } == ['start a 3 @0.0', 'start b 2 @0.0']
    }

    def "T[v] with a vehicle that is not picked finds none"() {
        when:
        def r = h.run('''
            v1 = pick { }
            v2 = pick { }
            release v2
            execute fly('a', 1)[v2]
        ''')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.line == 5
        r.error.message.contains('no vehicles to run task a{ 2 }')
    }

    def "the operators are default methods of Task and Position: plain Groovy code builds the same tasks"() {
        given:
        def a = new FlyTask(h.platform, 'a', 1)
        def b = new FlyTask(h.platform, 'b', 1)
        def vs = NodeSet.of(h.platform.node('1'))

        expect:
        (a >> b) instanceof SequentialTask
        (a | b) instanceof ConcurrentTask
        (a / ({ true } as Condition)) instanceof ConstrainedTask
        a[vs] instanceof ResourceExplicitTask
        (a >> b | a[vs]).id == '((a >> b) | a{ 1 })'
        (Position.fromDegrees(0, 0, 0) ^ 5) == new Area(Position.fromDegrees(0, 0, 0), 5)
    }
}
