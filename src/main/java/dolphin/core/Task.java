package dolphin.core;

/**
 * A unit of work for zero or more vehicles. Tasks are inert values: building one has no effect;
 * {@link Environment#run} allocates vehicles and drives a fresh executor.
 *
 * <p>The default methods are the Dolphin operators; Groovy maps {@code >>}, {@code |}, {@code /}
 * and {@code [ ]} to them, so no metaclass change is needed.
 */
public interface Task {

    String getId();

    /**
     * The word a viewer shows for this kind of task ({@code sequence}, {@code concurrent},
     * {@code until}, {@code mission}...); its {@link #getId()} says which one.
     */
    default String kind() {
        return "task";
    }

    /** A new executor for one occurrence of this task. */
    TaskExecutor getExecutor();

    /**
     * Chooses vehicles for this occurrence from {@code available}, removes the ones it takes and
     * records them under {@code allocation}. Returns false when a requirement cannot be met.
     */
    boolean allocate(NodeSet available, Allocation allocation);

    /** {@code this >> next}: run next after this one is DONE. */
    default Task rightShift(Task next) {
        return new SequentialTask(this, next);
    }

    /** {@code this | other}: run both at once, on distinct vehicles. */
    default Task or(Task other) {
        return new ConcurrentTask(this, other);
    }

    /** {@code this / { cond }}: run until the condition holds. */
    default Task div(Condition until) {
        return new ConstrainedTask(this, until);
    }

    /** {@code this[vehicles]}: allocate only from the given set. */
    default Task getAt(NodeSet vehicles) {
        return new ResourceExplicitTask(this, vehicles);
    }
}
