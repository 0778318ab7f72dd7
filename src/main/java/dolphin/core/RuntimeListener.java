package dolphin.core;

/** Receives what the runtime has to tell: program messages and task events. Called on the script thread. */
public interface RuntimeListener {

    default void message(String text) {
    }

    default void taskEvent(TaskEvent event) {
    }
}
