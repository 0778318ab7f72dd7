package dolphin.dsl;

import dolphin.dsl.check.QuickFix;
import dolphin.dsl.check.ScriptText;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.ConstantExpression;
import org.codehaus.groovy.ast.expr.DeclarationExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MapEntryExpression;
import org.codehaus.groovy.ast.expr.MapExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;
import org.codehaus.groovy.control.SourceUnit;

/**
 * Rejects {@code execute v: task} when {@code v} is a {@code def} variable: execute keys name
 * script (binding) variables, and a local {@code def} is invisible to them. The fix takes the
 * {@code def} away.
 */
final class ExecuteKeyCheck extends ScriptCheck {

    @Override
    protected void check(SourceUnit source, ClassNode script) {
        ScriptText text = ScriptText.lazy(source);
        Map<String, DeclarationExpression> locals = new HashMap<>();
        List<MethodCallExpression> executes = new ArrayList<>();
        new Visitor(source) {
            @Override
            public void visitDeclarationExpression(DeclarationExpression d) {
                if (d.getLeftExpression() instanceof VariableExpression v) {
                    locals.putIfAbsent(v.getName(), d);
                }
                super.visitDeclarationExpression(d);
            }

            @Override
            public void visitMethodCallExpression(MethodCallExpression call) {
                if (isExecute(call)) {
                    executes.add(call);
                }
                super.visitMethodCallExpression(call);
            }
        }.visitClass(script);
        for (MethodCallExpression call : executes) {
            for (MapEntryExpression entry : namedArguments(call.getArguments())) {
                if (entry.getKeyExpression() instanceof ConstantExpression k && locals.containsKey(String.valueOf(k.getValue()))) {
                    String name = String.valueOf(k.getValue());
                    error(source, "execute: '" + name + "' is declared with 'def', so execute cannot see it: its keys name"
                            + " script variables. Expected an assignment without 'def', e.g. '" + name + " = pick { ... }'", k,
                            withoutDef(text, locals.get(name)));
                }
            }
        }
    }

    /** The fix: the 'def' of the declaration taken away, so it assigns a script variable. */
    private static QuickFix[] withoutDef(ScriptText text, DeclarationExpression d) {
        VariableExpression v = (VariableExpression) d.getLeftExpression();
        String written = text.between(d.getLineNumber(), d.getColumnNumber(), v.getLineNumber(), v.getColumnNumber());
        if (!written.matches("def\\s+")) {
            return new QuickFix[0];
        }
        return new QuickFix[] {new QuickFix("Remove 'def': make '" + v.getName() + "' a script variable", d.getLineNumber(),
                d.getColumnNumber(), v.getLineNumber(), v.getColumnNumber(), "")};
    }

    /**
     * An execute call, or a later link of its command chain, which may carry more entries:
     * {@code execute v1: waitFor {c} then t1, v2: t2} is {@code execute(v1: ...).then([v2: t2], t1)}.
     */
    private static boolean isExecute(MethodCallExpression call) {
        if (call.isImplicitThis()) {
            return "execute".equals(call.getMethodAsString());
        }
        return List.of("then", "run", "onError").contains(call.getMethodAsString())
                && call.getObjectExpression() instanceof MethodCallExpression previous && isExecute(previous);
    }

    private static List<MapEntryExpression> namedArguments(Expression args) {
        if (args instanceof TupleExpression t) {
            for (Expression e : t.getExpressions()) {
                if (e instanceof MapExpression m) {
                    return m.getMapEntryExpressions();
                }
            }
        }
        return List.of();
    }
}
