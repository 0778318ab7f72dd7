package dolphin.core

import dolphin.testing.FlyTask
import dolphin.testing.TestPlatform
import spock.lang.Specification
import spock.lang.Timeout

/** The shape of an execute's tree, given to listeners before it starts, and the occurrences its events name. */
@Timeout(30)
class TaskTreeSpec extends Specification {

    ManualClock clock = ManualClock.autoAdvancing()
    TestPlatform platform = new TestPlatform()
    List<Object> heard = new java.util.concurrent.CopyOnWriteArrayList()
    Environment env = new Environment(platform, clock, new RuntimeListener() {
        @Override
        void taskEvent(TaskEvent event) { heard << event }

        @Override
        void executeStarted(TaskTree tree) { heard << tree }
    })

    def setup() {
        platform.addNode('1', 'UAV', Position.fromDegrees(41.18, -8.70, 0), [])
        platform.addNode('2', 'UAV', Position.fromDegrees(41.19, -8.70, 0), [])
        env.select(NodeFilter.ANY, 2, 0)
    }

    def "the tree comes first, with kinds, labels and vehicles; every event names one of its nodes"() {
        given: '(survey / {battery low}) >> home | waitFor {ready} then idle, the first on vehicle 2 only'
        def survey = new FlyTask(platform, 'survey', 10)
        def cut = new ConstrainedTask(survey, { clock.seconds() >= 4 } as Condition)
        def left = new ResourceExplicitTask(new SequentialTask(cut, new FlyTask(platform, 'home', 2)), NodeSet.of(platform.node('2')))
        def right = new ChoiceTask([new TaskGuard({ true } as Condition, new IdleTask(1))])
        def task = new ConcurrentTask(left, right)

        when:
        def end = env.run(task)
        TaskTree tree = heard[0] as TaskTree
        List<TaskEvent> events = heard.tail() as List<TaskEvent>

        then:
        end.isDone()
        tree.kind() == 'concurrent' && tree.label() == 'concurrent' && tree.vehicles() == ['2']   // the waitFor side needs no vehicle
        tree.children()[0].vehicles() == ['2']
        tree.children()*.kind() == ['sequence', 'waitFor']   // task[v] adds no node: it has no executor of its own
        tree.children()[0].children()*.kind() == ['until', 'platform task']
        tree.children()[0].children()[0].children()[0].label() == 'survey'
        tree.children()[0].children()[0].children()[0].vehicles() == ['2']
        tree.children()[1].children()[0].kind() == 'idle' && tree.children()[1].children()[0].label() == 'idle 1.0 s'

        and: 'each event names a node of the tree, and every node started'
        def occurrences = nodes(tree)*.occurrence() as Set
        events.every { it.occurrence() in occurrences }
        events.findAll { it.kind() == TaskEvent.Kind.STARTED }*.occurrence() as Set == occurrences

        and: 'the survey was stopped by its condition, by occurrence'
        def surveyNode = tree.children()[0].children()[0].children()[0]
        events.find { it.occurrence() == surveyNode.occurrence() && it.kind() == TaskEvent.Kind.STOPPED }
    }

    def "two occurrences of one task are two nodes"() {
        given:
        def hop = new FlyTask(platform, 'hop', 1)

        when:
        env.run(new SequentialTask(hop, hop))
        TaskTree tree = heard[0] as TaskTree

        then:
        tree.children()*.label() == ['hop', 'hop']
        tree.children()[0].occurrence() != tree.children()[1].occurrence()
        (heard.tail() as List<TaskEvent>).findAll { it.task().is(hop) }*.occurrence().unique().size() == 2
    }

    static List<TaskTree> nodes(TaskTree t) {
        [t] + t.children().collectMany { nodes(it) }
    }
}
