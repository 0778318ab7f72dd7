package dolphin.core;

/**
 * Receives what the runtime has to tell: program messages and task events, called on the script
 * thread, and vehicle events, called on the thread that raised them.
 */
public interface RuntimeListener {

    default void message(String text) {
    }

    default void taskEvent(TaskEvent event) {
    }

    /** An execute's task tree, allocated, just before its root starts; its nodes' events follow. */
    default void executeStarted(TaskTree tree) {
    }

    /**
     * Something that happened to a vehicle (contact lost or regained, a pilot taking it over, ...),
     * whether or not a script or a task runs. Called on the thread that raised it, which is not the
     * script thread: the MAVLink platform's communications thread for contact, the script thread for
     * what a running mission notices. So an implementation must be thread-safe and quick, and should
     * not throw (what it throws is logged and dropped).
     */
    default void vehicleEvent(VehicleEvent event) {
    }
}
