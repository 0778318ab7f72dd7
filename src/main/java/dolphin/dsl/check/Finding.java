package dolphin.dsl.check;

import java.util.List;

/** A mistake the checker found: where (1-based line and column), what, and the corrections it knows. */
public record Finding(int line, int column, String message, List<QuickFix> fixes) {

    public Finding {
        fixes = List.copyOf(fixes);
    }
}
