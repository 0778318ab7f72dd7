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
 * longer in an onError block. In an assignment, {@code x = watch(t) onError { ... } >> next} is
 * {@code (x = watch(t) onError { ... }) >> next}: next is joined to what was assigned, and dropped.
 * The fix puts the watch in parentheses.
 */
final class HandlerOperandCheck extends ScriptCheck {

    @Override
    protected void check(SourceUnit source, ClassNode script) {
        ScriptText text = ScriptText.lazy(source);
        new Visitor(source) {
            @Override
            public void visitMethodCallExpression(MethodCallExpression call) {
                List<Expression> args = arguments(call);
                if (isOnError(call) && !args.isEmpty() && args.get(args.size() - 1) instanceof BinaryExpression b
                        && b.getLeftExpression() instanceof ClosureExpression handler) {
                    String rest = rest(b);
                    error(source, "'" + rest + "' after the onError block applies to the block, not to the watch: Groovy joins '{ ... } "
                            + rest + "' before it hands it to onError. Expected the watch in parentheses: '(watch(t) onError { ... }) "
                            + rest + "'", b, parenthesized(text, call, handler));
                }
                super.visitMethodCallExpression(call);
            }

            @Override
            public void visitBinaryExpression(BinaryExpression b) {
                // x = watch(t) onError { ... } >> next is (x = watch(t) onError { ... }) >> next
                if (b.getLeftExpression() instanceof BinaryExpression assignment && "=".equals(assignment.getOperation().getText())
                        && assignment.getRightExpression() instanceof MethodCallExpression call && isOnError(call)
                        && !text.between(assignment.getLineNumber(), assignment.getColumnNumber() - 1, assignment.getLineNumber(),
                                assignment.getColumnNumber()).equals("(")
                        && arguments(call).get(arguments(call).size() - 1) instanceof ClosureExpression handler) {
                    String rest = rest(b);
                    error(source, "'" + rest + "' after the onError block applies to the assignment, not to the watch: Groovy reads"
                            + " 'x = watch(t) onError { ... } " + rest + "' as '(x = watch(t) onError { ... }) " + rest + "', whose"
                            + " result is dropped. Expected the watch in parentheses: '(watch(t) onError { ... }) " + rest + "'",
                            call.getMethod(), parenthesized(text, call, handler));
                }
                super.visitBinaryExpression(b);
            }
        }.visitClass(script);
    }

    private static boolean isOnError(MethodCallExpression call) {
        return !call.isImplicitThis() && "onError".equals(call.getMethodAsString());
    }

    /** The operator and what follows it, as the message shows them: "/ ...", "[...]". */
    private static String rest(BinaryExpression b) {
        String op = b.getOperation().getText();
        return "[".equals(op) ? "[...]" : op + " ...";
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
