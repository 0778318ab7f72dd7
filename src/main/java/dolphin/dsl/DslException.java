package dolphin.dsl;

/** A mistake in how a script uses a DSL word; reported with the script's file and line. */
public final class DslException extends RuntimeException {
    public DslException(String message) {
        super(message);
    }
}
