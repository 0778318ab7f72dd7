package dolphin.dsl

import dolphin.core.Task
import dolphin.core.TaskGuard
import dolphin.dsl.vocabulary.Word

/** The {@code when { cond } then task} branches of allOf, oneOf and choose. */
class GuardedTaskSetBuilder {
    private final List<TaskGuard> guards = []

    static List<TaskGuard> build(String word, Closure branches) {
        GuardedTaskSetBuilder b = new GuardedTaskSetBuilder()
        Blocks.run(branches, b)
        if (b.guards.isEmpty()) {
            throw new DslException("${word}: no choices were defined; expected one or more 'when { condition } then task'")
        }
        b.guards
    }

    @Word('A branch: when { condition } then task')
    DolphinScript.Then when(Closure condition) {
        new DolphinScript.Then({ Task t ->
            guards << new TaskGuard(new ClosureCondition(condition), t)
            t
        })
    }
}
