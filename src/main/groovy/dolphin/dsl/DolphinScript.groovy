package dolphin.dsl

import dolphin.core.AbstractNode
import dolphin.core.ActionTask
import dolphin.core.AllOfTask
import dolphin.core.Area
import dolphin.core.ChoiceTask
import dolphin.core.CompletionState
import dolphin.core.ConditionTask
import dolphin.core.ConstrainedTask
import dolphin.core.Environment
import dolphin.core.ErrorHandler
import dolphin.core.IdleTask
import dolphin.core.NodeSet
import dolphin.core.Position
import dolphin.core.NodeFilter
import dolphin.core.ResourceExplicitTask
import dolphin.core.StandInNode
import dolphin.core.Task
import dolphin.core.TaskGuard
import dolphin.core.TimeConstrainedTask
import dolphin.core.WatcherTask
import dolphin.dsl.vocabulary.Word
import org.codehaus.groovy.runtime.InvokerHelper

/**
 * The base class of every Dolphin script: the instructions of the language (docs/runtime-semantics.md).
 * Platform words come from {@link DslExtension#words} through {@link #methodMissing}.
 */
abstract class DolphinScript extends Script implements DslScript {

    /** Protected, not private: the script class is a subclass, and Groovy cannot reach a superclass's private members dynamically. */
    protected ScriptContext context

    /** An execute whose command chain has not yet supplied its task (see {@link #execute}). */
    protected PendingExecute pendingExecute

    @Override
    void attach(ScriptContext context) {
        this.context = context
    }

    /** The platform word objects of this run (also used to suggest names in errors). */
    List<Object> getPlatformWords() {
        context == null ? [] : context.words()
    }

    protected Environment env() {
        context.environment()
    }

    // ---- vehicles

    /** {@code pick { count 2; type 'UAV'; ... }}: binds free vehicles, waiting up to the timeout. */
    @Word('Binds free vehicles that match the clauses, waiting up to the timeout: v = pick { type \'UAV\'; count 2 }')
    NodeSet pick(@DelegatesTo(value = Picker, strategy = Closure.DELEGATE_FIRST) Closure clauses) {
        Picker picker = new Picker()
        Blocks.run(clauses, picker)
        if (context.rehearsal()) {
            return standIns(picker)
        }
        NodeSet chosen = env().select(picker.filter(), picker.requestedCount(), picker.requestedTimeout())
        if (chosen.is(NodeSet.EMPTY)) {
            throw new Halt("pick: could not find ${picker.requestedCount()} free vehicle(s) matching ${picker.filter()}"
                    + " within ${picker.requestedTimeout()} s; connected: ${env().platform.connectedNodes}, already picked: ${env().bound}")
        }
        chosen
    }

    /** What a rehearsal picks: as many vehicles as asked, none of them there. */
    private static NodeSet standIns(Picker picker) {
        NodeSet set = new NodeSet()
        NodeFilter f = picker.filter()
        (1..picker.requestedCount()).each { set.add(new StandInNode("stand-in ${it}", f.type() ?: 'any')) }
        set
    }

    @Word('Frees vehicles picked earlier, for other picks')
    void release(NodeSet vehicles) {
        env().release(vehicles)
    }

    @Word('How long a picked vehicle may be silent before its tasks fail (seconds): connectionTimeout = 30')
    void setConnectionTimeout(Number seconds) {
        env().setConnectionTimeout(seconds.doubleValue())
    }

    /** {@code setConnectionTimeout v1: 30, v2: 60}: keys name vehicle-set variables. */
    @Word('How long a picked vehicle may be silent before its tasks fail (seconds): connectionTimeout = 30')
    void setConnectionTimeout(Map<String, Number> timeouts) {
        timeouts.each { String key, Number secs ->
            vehicleSet('setConnectionTimeout', key).each { it.connectionTimeout = secs.doubleValue() }
        }
    }

    @Word('Where the vehicle is now (waits for its first report): a position in degrees and metres above mean sea level')
    Position position(NodeSet vehicle) {
        context.needsVehicle('position', vehicle)
        def node = vehicle.single('position')
        Position p = node instanceof AbstractNode ? ((AbstractNode) node).awaitPosition() : node.position
        if (p == null) {
            throw new DslException("position: vehicle ${node.id} has not reported a position yet")
        }
        p
    }

    @Word('The vehicle\'s remaining battery, 0 to 1 (waits for its first report)')
    double battery(NodeSet vehicle) {
        context.needsVehicle('battery', vehicle)
        def node = vehicle.single('battery')
        node instanceof AbstractNode ? ((AbstractNode) node).batteryRemaining() : 1.0d
    }

    // ---- running tasks

    /**
     * {@code execute task}, or {@code execute v1: t1, v2: t2, _: t3} (the entries run concurrently,
     * each on its vehicle set). Returns the final state; an ERROR is reported, not thrown.
     *
     * <p>Groovy reads {@code execute v1: waitFor {c} then task} as the command chain
     * {@code execute(v1: waitFor {c}).then(task)}, so execute may first get a half-built instruction
     * (waitFor/until/during/watch); it then returns a {@link PendingExecute} whose
     * {@code then}/{@code run}/{@code onError} completes it and runs everything (the report's examples
     * are written this way).
     */
    @Word('Runs a task, or tasks on vehicle sets at once (execute v1: t1, v2: t2), and waits for the end')
    Object execute(Object task) {
        if (pendingExecute != null) {
            throw pendingExecute.unfinished
        }
        if (task instanceof Task) {
            return executeTask((Task) task)
        }
        if (task instanceof Map) {
            return executeEntries((Map<String, Object>) task)
        }
        if (task instanceof Half) {
            return executeEntries(['_': task])
        }
        throw new DslException(task == null ? 'execute: the task is null (a variable that holds no task?)'
                : "execute: expected a task or 'v1: task1, v2: task2' entries, but got ${task.getClass().simpleName}")
    }

    protected CompletionState executeTask(Task task) {
        if (context.rehearsal()) {
            context.rehearsedExecute()
            return CompletionState.DONE
        }
        CompletionState cs = env().run(task)
        if (cs.error) {
            context.taskFailed()
        }
        cs
    }

    protected Object executeEntries(Map<String, Object> entries) {
        if (entries.isEmpty()) {
            throw new DslException('execute: no tasks given')
        }
        if (entries.values().any { it instanceof Half }) {
            pendingExecute = new PendingExecute(this, entries)
            return pendingExecute
        }
        Task all = null
        entries.each { String key, Object value ->
            if (!(value instanceof Task)) {
                throw new DslException("execute: the entry '${key}:' is not a task but ${value == null ? 'null' : value.getClass().simpleName}")
            }
            Task t = key == '_' ? (Task) value : new ResourceExplicitTask((Task) value, vehicleSet('execute', key))
            all = all == null ? t : all | t
        }
        executeTask(all)
    }

    /** The chain of a {@link PendingExecute} has supplied the missing task. */
    protected Object resumeExecute(Map<String, Object> entries) {
        pendingExecute = null
        executeEntries(entries)
    }

    /** Called by the engine when the script's code has run to its end. */
    @Override
    void scriptEnded() {
        if (pendingExecute != null) {
            throw pendingExecute.unfinished
        }
    }

    protected NodeSet vehicleSet(String word, String key) {
        if (!binding.hasVariable(key)) {
            throw new DslException("${word}: no script variable named '${key}'. Keys name vehicle sets held in script"
                    + " variables assigned without 'def', e.g. ${key} = pick { ... }")
        }
        def value = binding.getVariable(key)
        if (!(value instanceof NodeSet)) {
            throw new DslException("${word}: the key '${key}' does not identify a vehicle set: it holds "
                    + (value == null ? 'null' : value.getClass().simpleName))
        }
        (NodeSet) value
    }

    // ---- task constructors

    @Word('A task that waits until the condition holds, then runs the task after \'then\': waitFor { c } then t')
    Then waitFor(Closure condition) {
        new Then({ Task t -> new ChoiceTask([new TaskGuard(new ClosureCondition(condition), t)]) })
    }

    @Word('Runs the task after \'run\' until the condition holds, then stops it: until { c } run t (or t / { c })')
    Run until(Closure condition) {
        new Run('until { ... }', { Task t -> new ConstrainedTask(t, new ClosureCondition(condition)) })
    }

    /** {@code during { secs } run task}: the closure is evaluated once, now. */
    @Word('Runs the task after \'run\' for at most this many seconds: during 30 run t')
    Run during(Closure seconds) {
        during((Number) seconds.call())
    }

    @Word('Runs the task after \'run\' for at most this many seconds: during 30 run t')
    Run during(Number seconds) {
        new Run("during ${seconds}", { Task t -> new TimeConstrainedTask(t, seconds.doubleValue()) })
    }

    @Word('A task that does nothing for this many seconds')
    Task idle(Number seconds) {
        new IdleTask(seconds.doubleValue())
    }

    @Word('A task that runs the code once, at once')
    Task action(Closure code) {
        new ActionTask({ code.call() } as Runnable)
    }

    @Word('A task that ends when the condition holds')
    Task condition(Closure condition) {
        new ConditionTask(new ClosureCondition(condition))
    }

    @Word('Runs the task and handles its errors with the block after \'onError\': watch t onError { ignore() }')
    OnError watch(Task task) {
        new OnError(task)
    }

    @Word('A task that runs every branch whose condition holds: allOf { when { c } then t; ... }')
    Task allOf(@DelegatesTo(value = GuardedTaskSetBuilder, strategy = Closure.DELEGATE_FIRST) Closure branches) {
        new AllOfTask(GuardedTaskSetBuilder.build('allOf', branches))
    }

    @Word('A task that runs the first branch whose condition holds: oneOf { when { c } then t; ... }')
    Task oneOf(@DelegatesTo(value = GuardedTaskSetBuilder, strategy = Closure.DELEGATE_FIRST) Closure branches) {
        new ChoiceTask(GuardedTaskSetBuilder.build('oneOf', branches))
    }

    @Word('Another name for oneOf: runs the first branch whose condition holds')
    Task choose(@DelegatesTo(value = GuardedTaskSetBuilder, strategy = Closure.DELEGATE_FIRST) Closure branches) {
        new ChoiceTask(GuardedTaskSetBuilder.build('choose', branches))
    }

    @Word('The platform task with this id')
    Task task(String id) {
        env().platform.getPlatformTask(id)
    }

    // ---- program-level words

    @Word('Prints a message on the console (and the web view)')
    void message(Object text) {
        context.listener().message(String.valueOf(text))
    }

    @Word('Posts signals other branches can consume or poll: post ready: true')
    void post(Map<String, Object> signals) {
        context.signals().post(signals)
        message("posted ${signals}")
    }

    @Word('Takes posted signals if they are all there: true when it did')
    boolean consume(Map<String, Object> signals) {
        boolean ok = context.signals().consume(signals)
        if (ok) {
            message("consumed ${signals}")
        }
        ok
    }

    @Word('Whether a signal is posted (without taking it)')
    boolean poll(String key) {
        context.signals().poll(key)
    }

    @Word('Whether a signal is posted (without taking it)')
    boolean poll(Map<String, Closure> tests) {
        context.signals().poll(tests.collectEntries { k, c -> [k, { v -> c.call(v) as boolean } as java.util.function.Predicate] })
    }

    /** Asks for one line of input and evaluates it as script code, with this script's variables and words. */
    @Word('Asks the user for a line of input and evaluates it as script code')
    Object ask(String prompt) {
        String line = context.readInput(prompt)
        line == null ? null : context.evaluate(line)
    }

    @Word('Ends the script at once, with the reason')
    void halt(String why = 'halt') {
        throw new Halt(why)
    }

    @Word('Pauses the script for this many seconds')
    void pause(Number seconds) {
        env().pause(seconds.doubleValue())
    }

    /** Groovy's sleep, on the runtime's clock. */
    @Word('Pauses the script for this many milliseconds (Groovy\'s sleep, on the runtime\'s clock)')
    void sleep(long millis) {
        env().pause(millis / 1000d)
    }

    @Word('A position: latitude and longitude in degrees, height in metres above mean sea level')
    Position location(Number lat, Number lon, Number height = 0) {
        double la = lat.doubleValue()
        double lo = lon.doubleValue()
        if (!(la >= -90d && la <= 90d)) {
            throw new DslException("location: the latitude must be between -90 and 90 degrees, got ${lat}")
        }
        if (!(lo >= -180d && lo <= 180d)) {
            throw new DslException("location: the longitude must be between -180 and 180 degrees, got ${lon}")
        }
        Position.fromDegrees(la, lo, height.doubleValue())
    }

    @Word('A circular area: a centre and a radius in metres')
    Area area(Position center, Number radius) {
        new Area(center, radius.doubleValue())
    }

    /** Platform words: the first word object that has a matching method answers. */
    def methodMissing(String name, Object args) {
        Object[] argv = args instanceof Object[] ? (Object[]) args : [args] as Object[]
        for (Object words : platformWords) {
            if (InvokerHelper.getMetaClass(words).respondsTo(words, name, argv)) {
                return InvokerHelper.invokeMethod(words, name, argv)
            }
        }
        throw new MissingMethodException(name, getClass(), argv)
    }

    // ---- the second halves of two-word instructions

    /** The first half of a two-word instruction, waiting for its second: then, run or onError. */
    interface Half {
        /** How the first half reads, e.g. 'waitFor { ... }'. */
        String getOpening()

        /** The word that completes it. */
        String getClosing()

        Task complete(Object second)
    }

    /** {@code waitFor {c} then task}. */
    static final class Then implements Half {
        private final Closure<Task> make

        Then(Closure<Task> make) { this.make = make }

        @Word('The task that runs when the first half\'s condition holds')
        Task then(Task task) { make.call(task) }

        String getOpening() { 'waitFor { ... }' }

        String getClosing() { 'then' }

        Task complete(Object second) { then((Task) second) }
    }

    /** {@code until {c} run task}, {@code during secs run task}. */
    static final class Run implements Half {
        private final Closure<Task> make
        private final String opening

        Run(String opening, Closure<Task> make) {
            this.opening = opening
            this.make = make
        }

        @Word('The task the first half runs, bounded by its condition or time')
        Task run(Task task) { make.call(task) }

        String getOpening() { opening }

        String getClosing() { 'run' }

        Task complete(Object second) { run((Task) second) }
    }

    /** {@code watch task onError { msg -> ... }}; the handler may call ignore() or propagate() (the default). */
    static final class OnError implements Half {
        private final Task task

        OnError(Task task) { this.task = task }

        @Word('How watch handles the task\'s errors: ignore() or propagate() (the default)')
        Task onError(@DelegatesTo(value = ErrorDecision, strategy = Closure.DELEGATE_FIRST) Closure handler) {
            new WatcherTask(task, { String message ->
                ErrorDecision decision = new ErrorDecision()
                Blocks.run(handler, decision, message)
                decision.decision
            } as ErrorHandler)
        }

        String getOpening() { "watch ${task.id}" }

        String getClosing() { 'onError' }

        Task complete(Object second) { onError((Closure) second) }
    }

    /**
     * An execute waiting for the rest of its command chain: {@code execute v1: waitFor {c} then t1, v2: t2}
     * is {@code execute(v1: waitFor {c}).then([v2: t2], t1)}. The chain's call completes the half-built
     * entry, adds the entries that came with it and runs them all (or waits again for another half).
     */
    static final class PendingExecute {
        private final DolphinScript script
        private final Map<String, Object> entries
        /** Thrown if the chain never completes; made here, so it carries the execute's line. */
        final DslException unfinished

        PendingExecute(DolphinScript script, Map<String, Object> entries) {
            this.script = script
            this.entries = new LinkedHashMap<>(entries)
            def open = this.entries.find { it.value instanceof Half }
            Half half = (Half) open.value
            String what = open.key == '_' ? "'${half.opening}'" : "the entry '${open.key}: ${half.opening}'"
            unfinished = new DslException("execute: ${what} has no '${half.closing}' part. Expected"
                    + " '${half.opening} ${half.closing} ...' with '${half.closing}' on the same line")
        }

        Object then(Task task) { complete('then', task, [:]) }

        Object then(Map<String, Object> more, Task task) { complete('then', task, more) }

        Object run(Task task) { complete('run', task, [:]) }

        Object run(Map<String, Object> more, Task task) { complete('run', task, more) }

        Object onError(Closure handler) { complete('onError', handler, [:]) }

        Object onError(Map<String, Object> more, Closure handler) { complete('onError', handler, more) }

        private Object complete(String word, Object second, Map<String, Object> more) {
            List<String> open = entries.findAll { it.value instanceof Half }.collect { it.key }
            if (open.size() != 1) {
                throw new DslException("execute: the entries ${open.collect { "'${it}:'" }.join(', ')} each lack their"
                        + " second half; expected each in parentheses, e.g. v1: (waitFor { c } then task)")
            }
            Half half = (Half) entries[open[0]]
            if (half.closing != word) {
                throw new DslException("execute: '${half.opening}' is followed by '${word}'; expected '${half.closing}'")
            }
            entries[open[0]] = half.complete(second)
            entries.putAll(more)
            script.resumeExecute(entries)
        }
    }

    /** The delegate of an onError handler. Each error starts with propagate. */
    static final class ErrorDecision {
        ErrorHandler.Decision decision = ErrorHandler.Decision.PROPAGATE

        @Word('The watched task\'s error is ignored: the task counts as done')
        void ignore() { decision = ErrorHandler.Decision.IGNORE }

        @Word('The watched task\'s error goes on to the enclosing task (the default)')
        void propagate() { decision = ErrorHandler.Decision.PROPAGATE }
    }
}
