package dolphin.dsl;

import dolphin.dsl.check.QuickFix;
import java.util.List;

/**
 * A mistake in a script, located: {@code file:line[:column]: message}. Line and column are 0 when
 * unknown. {@code fixes} are the corrections the check knows, which editors offer as quick fixes.
 */
public record ScriptError(String file, int line, int column, String message, List<QuickFix> fixes) {

    public ScriptError {
        fixes = List.copyOf(fixes);
    }

    public ScriptError(String file, int line, int column, String message) {
        this(file, line, column, message, List.of());
    }

    @Override
    public String toString() {
        return file + (line > 0 ? ":" + line + (column > 0 ? ":" + column : "") : "") + ": " + message;
    }
}
