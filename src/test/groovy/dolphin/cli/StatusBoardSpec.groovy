package dolphin.cli

import dolphin.core.CompletionState
import dolphin.core.TaskEvent
import dolphin.mission.flight.MissionTask
import dolphin.mission.model.Mission
import spock.lang.Specification

/** The task column of the status table: the state in lower case, a task's error as the task wrote it. */
class StatusBoardSpec extends Specification {

    static final MissionTask SURVEY = new MissionTask(new Mission('Survey Area 1', null, []))

    static String column(TaskEvent.Kind kind, CompletionState state) {
        StatusBoard board = new StatusBoard()
        board.taskEvent(new TaskEvent(kind, SURVEY, ['1'], state, 12.5, 1))
        board.tasks['1']
    }

    def "#kind shows as '#shown'"() {
        expect:
        column(kind, state) == shown

        where:
        kind                     | state                                                                      || shown
        TaskEvent.Kind.STARTED   | CompletionState.IN_PROGRESS                                                || 'Survey Area 1 running'
        TaskEvent.Kind.STOPPED   | CompletionState.IN_PROGRESS                                                || 'Survey Area 1 stopped'
        TaskEvent.Kind.COMPLETED | CompletionState.DONE                                                       || 'Survey Area 1 done'
        TaskEvent.Kind.COMPLETED | CompletionState.error('left AUTO for RTL during item 2 of 20 (NAV_WAYPOINT)') ||
                'Survey Area 1 error: left AUTO for RTL during item 2 of 20 (NAV_WAYPOINT)'
    }
}
