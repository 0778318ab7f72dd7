package dolphin.dsl;

import dolphin.dsl.check.QuickFix;
import dolphin.dsl.check.ScriptText;
import java.util.Map;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.BinaryExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.control.SourceUnit;

/**
 * Finds {@code execute (a >> b) / { c }}: a parenthesis right after {@code execute} holds its whole
 * argument list for Groovy, so the operator after it applies to what execute returned, once the
 * task has already run without it. The constraint (or sequence, or vehicles) would be lost. The fix
 * puts the whole task inside execute's parentheses.
 */
final class ExecuteOperandCheck extends ScriptCheck {

    private static final Map<String, String> OPERATORS = Map.of("/", "/ { condition }", ">>", ">> task", "|", "| task",
            "[", "[vehicles]");

    @Override
    protected void check(SourceUnit source, ClassNode script) {
        ScriptText text = ScriptText.lazy(source);
        new Visitor(source) {
            @Override
            public void visitBinaryExpression(BinaryExpression b) {
                String op = b.getOperation().getText();
                if (OPERATORS.containsKey(op) && b.getLeftExpression() instanceof MethodCallExpression call
                        && call.isImplicitThis() && "execute".equals(call.getMethodAsString())) {
                    String rest = OPERATORS.get(op);
                    error(source, "execute: Groovy takes the parentheses after 'execute' as its whole argument list, so '"
                            + rest + "' would apply to execute's result after the task ran without it. Expected the"
                            + " whole task inside execute's parentheses, e.g. 'execute((a >> b) " + rest + ")', or no"
                            + " parenthesis right after execute: 'execute _: (a >> b) " + rest + "'", call, whole(text, call, b));
                }
                super.visitBinaryExpression(b);
            }
        }.visitClass(script);
    }

    /** The fix: {@code execute (a >> b) / { c }} becomes {@code execute((a >> b) / { c })}. */
    private static QuickFix[] whole(ScriptText text, MethodCallExpression execute, BinaryExpression b) {
        String written = text.between(execute.getLineNumber(), execute.getColumnNumber(), b.getLastLineNumber(), b.getLastColumnNumber());
        if (!written.startsWith("execute") || b.getLastLineNumber() < 1) {
            return new QuickFix[0];
        }
        return new QuickFix[] {new QuickFix("Put the whole task inside execute's parentheses", execute.getLineNumber(),
                execute.getColumnNumber(), b.getLastLineNumber(), b.getLastColumnNumber(),
                "execute(" + written.substring("execute".length()).strip() + ")")};
    }
}
