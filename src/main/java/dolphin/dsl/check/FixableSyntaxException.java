package dolphin.dsl.check;

import java.util.List;
import org.codehaus.groovy.syntax.SyntaxException;

/**
 * A compile error of a check that knows how to correct it: Groovy's error collector carries it to
 * the compiler's caller, which hands the fixes on with the error (editors offer them as quick fixes).
 */
public final class FixableSyntaxException extends SyntaxException {

    private final transient List<QuickFix> fixes;

    public FixableSyntaxException(String message, int line, int column, List<QuickFix> fixes) {
        super(message, line, column);
        this.fixes = List.copyOf(fixes);
    }

    public List<QuickFix> fixes() {
        return fixes;
    }
}
