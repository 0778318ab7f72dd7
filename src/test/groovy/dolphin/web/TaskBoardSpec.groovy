package dolphin.web

import dolphin.core.CompletionState
import dolphin.core.IdleTask
import dolphin.core.TaskEvent
import dolphin.core.TaskTree
import dolphin.testing.FlyTask
import dolphin.testing.TestPlatform
import spock.lang.Specification

/** The task trees and node states the page shows, from the engine's events (no clock, no threads). */
class TaskBoardSpec extends Specification {

    TaskBoard board = new TaskBoard(100)
    def survey = new FlyTask(new TestPlatform(), 'Survey Area 1', 10)
    def home = new FlyTask(new TestPlatform(), 'Return to base 1', 10)

    /** sequence(until(survey), home) on vehicle 1; waitFor(idle) beside it */
    TaskTree tree = new TaskTree(1, 'concurrent', 'concurrent', ['1'], [
            new TaskTree(2, 'sequence', 'sequence', ['1'], [
                    new TaskTree(3, 'until', 'until', ['1'], [new TaskTree(4, 'platform task', 'Survey Area 1', ['1'], [])]),
                    new TaskTree(5, 'platform task', 'Return to base 1', ['1'], [])]),
            new TaskTree(6, 'waitFor', 'waitFor', [], [new TaskTree(7, 'idle', 'idle 1.0 s', [], [])])])

    static TaskEvent event(TaskEvent.Kind kind, def task, long occurrence, double time, CompletionState state = CompletionState.UNDEFINED) {
        new TaskEvent(kind, task, task instanceof FlyTask ? ['1'] : [], state, time, occurrence)
    }

    Map node(long occurrence) {
        find(board.json(), occurrence)
    }

    static Map find(List nodes, long occurrence) {
        nodes.findResult { Map n -> n.occurrence == occurrence ? n : find(n.children as List, occurrence) } as Map
    }

    def "nodes wait, run, are stopped or done; times count from the run's start"() {
        given:
        board.executeStarted(tree)
        def idle = new IdleTask(1)

        expect: 'all waiting before the root starts'
        node(4).state == 'waiting' && node(4).since == null

        when:
        [1, 2, 3, 4, 6].each { board.taskEvent(event(TaskEvent.Kind.STARTED, it == 4 ? survey : idle, it, 101.25)) }

        then:
        node(4).state == 'running' && node(4).since == 1.3
        node(3).detail == 'until its condition holds'
        node(6).detail == 'waiting for a condition'
        node(5).state == 'waiting'

        when: 'the battery cut stops the survey; the return flies and is done'
        board.taskEvent(event(TaskEvent.Kind.STOPPED, survey, 4, 130))
        board.taskEvent(event(TaskEvent.Kind.COMPLETED, idle, 3, 130, CompletionState.DONE))
        board.taskEvent(event(TaskEvent.Kind.STARTED, home, 5, 130))

        then:
        node(4).state == 'stopped' && node(4).since == 30.0
        node(5).state == 'running'
        board.vehicleTasks()['1'] == 'Return to base 1 running'

        when:
        board.taskEvent(event(TaskEvent.Kind.COMPLETED, home, 5, 150, CompletionState.DONE))

        then:
        node(5).state == 'done'
        board.vehicleTasks()['1'] == 'Return to base 1 done'
    }

    def "an error carries its message; nodes that never ran are skipped when the execute ends"() {
        given:
        board.executeStarted(tree)
        def idle = new IdleTask(1)
        [1, 2, 3, 4].each { board.taskEvent(event(TaskEvent.Kind.STARTED, it == 4 ? survey : idle, it, 100)) }

        when:
        board.taskEvent(event(TaskEvent.Kind.COMPLETED, survey, 4, 110, CompletionState.error('vehicle 1 lost')))
        board.taskEvent(event(TaskEvent.Kind.COMPLETED, idle, 1, 110, CompletionState.error('vehicle 1 lost')))

        then:
        node(4).state == 'error' && node(4).detail == 'vehicle 1 lost'
        node(5).state == 'skipped'
        node(7).state == 'skipped'
        node(3).state == 'running'   // its own end never came in this test
    }

    def "the version moves with each change, and only the last executes are kept"() {
        given:
        long before = board.version()

        when:
        (1..TaskBoard.KEPT + 3).each { board.executeStarted(new TaskTree(1000 + it, 'idle', 'idle 1.0 s', [], [])) }

        then:
        board.version() == before + TaskBoard.KEPT + 3
        board.json().size() == TaskBoard.KEPT
        board.json()[0].occurrence == 1004
    }
}
