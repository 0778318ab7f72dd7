package dolphin.dsl;

import dolphin.dsl.check.QuickFix;
import dolphin.dsl.check.ScriptText;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MapExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;
import org.codehaus.groovy.ast.stmt.BlockStatement;
import org.codehaus.groovy.ast.stmt.ExpressionStatement;
import org.codehaus.groovy.ast.stmt.Statement;
import org.codehaus.groovy.control.SourceUnit;

/**
 * Finds the second word of a two-word instruction at the start of a statement, as the report prints
 * its examples, with {@code then (...)} on the line below {@code waitFor { ... }}: Groovy
 * ends the statement at the line break, so {@code then} becomes a call of its own. The fix joins the
 * lines. Inside a statement ({@code execute v: watch t onError {...}}) the words were paired
 * differently; the fix puts the task in parentheses.
 */
final class SplitInstructionCheck extends ScriptCheck {

    /** Second word, and the first words it belongs to. */
    private static final Map<String, String> SECOND_WORDS = Map.of(
            "then", "waitFor { condition }' or 'when { condition }",
            "run", "until { condition }' or 'during ...",
            "onError", "watch task");

    /** The first word that takes its task without a block: 'watch t onError' read as 'watch.t(onError ...)'. */
    private static final Map<String, String> TASK_OPENERS = Map.of("onError", "watch", "run", "during");

    @Override
    protected void check(SourceUnit source, ClassNode script) {
        ScriptText text = ScriptText.lazy(source);
        Map<Expression, Statement> previous = new IdentityHashMap<>();
        Map<MethodCallExpression, MethodCallExpression> callers = new IdentityHashMap<>();
        new Visitor(source) {
            private Expression statement;

            @Override
            public void visitExpressionStatement(ExpressionStatement s) {
                statement = s.getExpression();
                super.visitExpressionStatement(s);
            }

            @Override
            public void visitBlockStatement(BlockStatement block) {
                List<Statement> statements = block.getStatements();
                for (int i = 1; i < statements.size(); i++) {
                    if (statements.get(i) instanceof ExpressionStatement s) {
                        previous.put(s.getExpression(), statements.get(i - 1));
                    }
                }
                super.visitBlockStatement(block);
            }

            @Override
            public void visitMethodCallExpression(MethodCallExpression call) {
                for (Expression a : arguments(call)) {
                    if (a instanceof MethodCallExpression inner) {
                        callers.put(inner, call);
                    }
                }
                String word = call.getMethodAsString();
                // Script's own run(File, String[]) takes two arguments; a split 'run task' has one
                if (call.isImplicitThis() && SECOND_WORDS.containsKey(word)
                        && !("run".equals(word) && arguments(call).size() != 1)) {
                    if (call == statement) {
                        error(source, split(word), call, joined(text, previous.get(call), call));
                    } else {
                        error(source, nested(word), call, parenthesized(text, word, callers.get(call)));
                    }
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

    /** The second word moved up to the end of the statement before it, when only blanks lie between. */
    private static QuickFix[] joined(ScriptText text, Statement before, MethodCallExpression call) {
        if (before == null || before.getLastLineNumber() < 1
                || !text.between(before.getLastLineNumber(), before.getLastColumnNumber(), call.getLineNumber(), call.getColumnNumber()).isBlank()) {
            return new QuickFix[0];
        }
        return new QuickFix[] {new QuickFix("Join '" + call.getMethodAsString() + "' to the line above", before.getLastLineNumber(),
                before.getLastColumnNumber(), call.getLineNumber(), call.getColumnNumber(), " ")};
    }

    /**
     * {@code watch t onError {...}} read as {@code (watch).t(onError {...})}: the caller is the call
     * of {@code t} on what ends with the variable {@code watch}; the fix writes {@code watch(t)}.
     */
    private static QuickFix[] parenthesized(ScriptText text, String word, MethodCallExpression caller) {
        String opener = TASK_OPENERS.get(word);
        String task = caller.getMethodAsString();
        if (caller == null || opener == null || task == null || caller.isImplicitThis() || !(caller.getObjectExpression() instanceof MethodCallExpression before)) {
            return new QuickFix[0];
        }
        List<Expression> args = arguments(before);
        Expression last = args.isEmpty() ? null : args.get(args.size() - 1);
        if (last instanceof MapExpression map && !map.getMapEntryExpressions().isEmpty()) {
            last = map.getMapEntryExpressions().get(map.getMapEntryExpressions().size() - 1).getValueExpression();
        }
        if (!(last instanceof VariableExpression v) || !opener.equals(v.getName())) {
            return new QuickFix[0];
        }
        Expression name = caller.getMethod();
        String written = text.between(v.getLineNumber(), v.getColumnNumber(), name.getLastLineNumber(), name.getLastColumnNumber());
        if (!written.matches(opener + "\\s+" + Pattern.quote(task))) {
            return new QuickFix[0];
        }
        return new QuickFix[] {new QuickFix("Write '" + opener + "(" + task + ")'", v.getLineNumber(), v.getColumnNumber(),
                name.getLastLineNumber(), name.getLastColumnNumber(), opener + "(" + task + ")")};
    }
}
