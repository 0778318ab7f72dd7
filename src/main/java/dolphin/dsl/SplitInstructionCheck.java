package dolphin.dsl;

import java.util.Map;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.ArgumentListExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.ast.stmt.ExpressionStatement;
import org.codehaus.groovy.control.SourceUnit;

/**
 * Finds the second word of a two-word instruction at the start of a statement, as the report prints
 * its examples, with {@code then (...)} on the line below {@code waitFor { ... }}: Groovy
 * ends the statement at the line break, so {@code then} becomes a call of its own.
 */
final class SplitInstructionCheck extends ScriptCheck {

    /** Second word, and the first words it belongs to. */
    private static final Map<String, String> SECOND_WORDS = Map.of(
            "then", "waitFor { condition }' or 'when { condition }",
            "run", "until { condition }' or 'during ...",
            "onError", "watch task");

    @Override
    protected void check(SourceUnit source, ClassNode script) {
        new Visitor(source) {
            private Expression statement;

            @Override
            public void visitExpressionStatement(ExpressionStatement s) {
                statement = s.getExpression();
                super.visitExpressionStatement(s);
            }

            @Override
            public void visitMethodCallExpression(MethodCallExpression call) {
                String word = call.getMethodAsString();
                // Script's own run(File, String[]) takes two arguments; a split 'run task' has one
                if (call.isImplicitThis() && SECOND_WORDS.containsKey(word)
                        && !("run".equals(word) && arguments(call) != 1)) {
                    error(source, call == statement ? split(word) : nested(word), call);
                }
                super.visitMethodCallExpression(call);
            }
        }.visitClass(script);
    }

    private static String split(String word) {
        String opening = SECOND_WORDS.get(word);
        return "'" + word + "' begins a new statement: Groovy ended the statement before it at the line"
                + " break, so the '" + opening + "' above did not get its '" + word + "' part. Expected '"
                + word + "' on the same line as the end of '" + opening + "', with the rest of the task on"
                + " the next lines if needed";
    }

    /** Inside a statement, as in {@code execute v: watch t onError {...}}: Groovy chained the words differently. */
    private static String nested(String word) {
        String opening = SECOND_WORDS.get(word);
        return "'" + word + "' is read here as an argument of what comes before it, not as the second word of '"
                + opening + "' (Groovy pairs the words of a command chain two by two). Expected the task in"
                + " parentheses, e.g. 'execute v: watch(t) onError { ... }' or 'execute v: waitFor { c } then (t)'";
    }

    private static int arguments(MethodCallExpression call) {
        return call.getArguments() instanceof TupleExpression t ? t.getExpressions().size()
                : call.getArguments() instanceof ArgumentListExpression a ? a.getExpressions().size() : 1;
    }
}
