package dolphin.dsl;

/** Implemented by the scripts' base class, so the Java engine can hand it its context. */
public interface DslScript {
    void attach(ScriptContext context);
}
