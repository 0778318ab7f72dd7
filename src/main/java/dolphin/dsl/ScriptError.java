package dolphin.dsl;

/** A mistake in a script, located: {@code file:line[:column]: message}. Line and column are 0 when unknown. */
public record ScriptError(String file, int line, int column, String message) {

    @Override
    public String toString() {
        return file + (line > 0 ? ":" + line + (column > 0 ? ":" + column : "") : "") + ": " + message;
    }
}
