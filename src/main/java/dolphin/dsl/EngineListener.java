package dolphin.dsl;

import dolphin.core.RuntimeListener;

/** What an embedding (IDE, GUI, the command line) hears from an {@link Engine}. */
public interface EngineListener extends RuntimeListener {

    default void scriptStarted(String name) {
    }

    default void scriptFinished(String name, ScriptResult result) {
    }
}
