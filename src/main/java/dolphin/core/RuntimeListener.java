package dolphin.core;

/** Receives what the runtime has to tell: program messages and task events. Called on the script thread. */
public interface RuntimeListener {

    default void message(String text) {
    }

    default void taskEvent(TaskEvent event) {
    }

    /** An execute's task tree, allocated, just before its root starts; its nodes' events follow. */
    default void executeStarted(TaskTree tree) {
    }
}
