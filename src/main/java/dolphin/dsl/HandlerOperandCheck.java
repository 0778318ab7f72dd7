package dolphin.dsl;

import dolphin.dsl.check.QuickFix;
import dolphin.dsl.check.ScriptText;
import java.util.List;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.BinaryExpression;
import org.codehaus.groovy.ast.expr.ClosureExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MapExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.control.SourceUnit;

/**
 * Finds {@code watch(t) onError { ... } >> next}: Groovy joins {@code { ... } >> next} before it
 * hands it to onError, so the operator applies to the handler (Groovy composes closures with
 * {@code >>}), not to the watch; {@code next} never runs as a task, and the handler's words are no
 * longer in an onError block. The fix puts the watch in parentheses.
 */
final class HandlerOperandCheck extends ScriptCheck {

    @Override
    protected void check(SourceUnit source, ClassNode script) {
        ScriptText text = ScriptText.lazy(source);
        new Visitor(source) {
            @Override
            public void visitMethodCallExpression(MethodCallExpression call) {
                List<Expression> args = arguments(call);
                if (!call.isImplicitThis() && "onError".equals(call.getMethodAsString()) && !args.isEmpty()
                        && args.get(args.size() - 1) instanceof BinaryExpression b && b.getLeftExpression() instanceof ClosureExpression handler) {
                    String op = b.getOperation().getText();
                    String rest = "[".equals(op) ? "[...]" : op + " ...";
                    error(source, "'" + rest + "' after the onError block applies to the block, not to the watch: Groovy joins '{ ... } "
                            + rest + "' before it hands it to onError. Expected the watch in parentheses: '(watch(t) onError { ... }) "
                            + rest + "'", b, parenthesized(text, call, handler));
                }
                super.visitMethodCallExpression(call);
            }
        }.visitClass(script);
    }

    /**
     * The fix: the watch and its handler in parentheses. A watch given to execute without a key gets
     * the key {@code _:} too, since a parenthesis right after execute would hold its whole argument list.
     */
    private static QuickFix[] parenthesized(ScriptText text, MethodCallExpression onError, ClosureExpression handler) {
        Expression watch = onError.getObjectExpression();
        boolean keyless = false;
        if (watch instanceof MethodCallExpression r && r.isImplicitThis() && "execute".equals(r.getMethodAsString())) {
            List<Expression> args = arguments(r);
            watch = args.isEmpty() ? null : args.get(args.size() - 1);
            if (watch instanceof MapExpression map && !map.getMapEntryExpressions().isEmpty()) {
                watch = map.getMapEntryExpressions().get(map.getMapEntryExpressions().size() - 1).getValueExpression();
            } else {
                keyless = true;
            }
        }
        if (!(watch instanceof MethodCallExpression w) || !"watch".equals(w.getMethodAsString()) || handler.getLastLineNumber() < 1) {
            return new QuickFix[0];
        }
        String written = text.between(w.getLineNumber(), w.getColumnNumber(), handler.getLastLineNumber(), handler.getLastColumnNumber());
        if (!written.startsWith("watch") || !written.endsWith("}")) {
            return new QuickFix[0];
        }
        return new QuickFix[] {new QuickFix("Put the watch in parentheses", w.getLineNumber(), w.getColumnNumber(),
                handler.getLastLineNumber(), handler.getLastColumnNumber(), (keyless ? "_: (" : "(") + written + ")")};
    }
}
