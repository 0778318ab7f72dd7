package dolphin.dsl;

/** Implemented by the scripts' base class, so the Java engine can hand it its context. */
public interface DslScript {
    void attach(ScriptContext context);

    /** Called after the script's code has run to its end; may throw to report an unfinished instruction. */
    default void scriptEnded() {
    }
}
