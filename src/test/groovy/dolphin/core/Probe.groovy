package dolphin.core

/**
 * A platform task for core specs: its steps follow a closure of the executor (typically of
 * {@code timeElapsed()}), and every init, start, step, completion and stop goes to a {@link Journal}
 * with the vehicles of that occurrence and the clock time. With no requirement it needs no vehicle.
 */
class Probe extends PlatformTask {

    final Journal journal
    final List<NodeFilter> filters
    final Closure<CompletionState> behaviour

    Probe(Journal journal, String id, List<NodeFilter> filters, Closure<CompletionState> behaviour) {
        super(id)
        this.journal = journal
        this.filters = List.copyOf(filters)
        this.behaviour = behaviour
    }

    /** DONE at the first step at which {@code seconds} have elapsed since its start. */
    static Probe lasting(Journal j, String id, double seconds, int vehicles = 1) {
        new Probe(j, id, [NodeFilter.ANY] * vehicles, { TaskExecutor ex ->
            ex.timeElapsed() >= seconds ? CompletionState.DONE : CompletionState.IN_PROGRESS
        })
    }

    /** ERROR with {@code message} at the first step at which {@code after} seconds have elapsed. */
    static Probe failing(Journal j, String id, double after, String message, int vehicles = 1) {
        new Probe(j, id, [NodeFilter.ANY] * vehicles, { TaskExecutor ex ->
            ex.timeElapsed() >= after ? CompletionState.error(message) : CompletionState.IN_PROGRESS
        })
    }

    /** Never ends by itself. */
    static Probe endless(Journal j, String id, int vehicles = 1) {
        lasting(j, id, Double.POSITIVE_INFINITY, vehicles)
    }

    /** Needs one vehicle per filter; DONE after {@code seconds}. */
    static Probe requiring(Journal j, String id, List<NodeFilter> filters, double seconds = 1) {
        new Probe(j, id, filters, { TaskExecutor ex ->
            ex.timeElapsed() >= seconds ? CompletionState.DONE : CompletionState.IN_PROGRESS
        })
    }

    @Override
    List<NodeFilter> getRequirements() { filters }

    @Override
    PlatformTaskExecutor getExecutor() {
        Probe probe = this
        new PlatformTaskExecutor(this) {
            @Override
            protected void onInitialize(Allocation allocation) { probe.note('init', this) }

            @Override
            protected void onStart() { probe.note('start', this) }

            @Override
            protected CompletionState onStep() {
                probe.note('step', this)
                probe.behaviour.call(this)
            }

            @Override
            protected void onCompletion() { probe.note(getCompletionState().isError() ? 'error' : 'done', this) }

            @Override
            protected void onStop() { probe.note('stop', this) }
        }
    }

    void note(String kind, TaskExecutor ex) {
        journal.record(kind, getId(), ex.getVehicles()*.getId(), ex.context().clock().seconds())
    }
}
