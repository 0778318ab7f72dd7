package dolphin.dsl;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.ConstantExpression;
import org.codehaus.groovy.ast.expr.DeclarationExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MapEntryExpression;
import org.codehaus.groovy.ast.expr.MapExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.control.messages.SyntaxErrorMessage;
import org.codehaus.groovy.syntax.SyntaxException;

/**
 * Rejects {@code execute v: task} when {@code v} is a {@code def} variable: execute keys name
 * script (binding) variables, and a local {@code def} is invisible to them (reference A.0).
 */
final class ExecuteKeyCheck extends CompilationCustomizer {

    ExecuteKeyCheck() {
        super(CompilePhase.CONVERSION);
    }

    @Override
    public void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
        if (!classNode.isScript()) {
            return;
        }
        Set<String> locals = new HashSet<>();
        List<MethodCallExpression> executes = new java.util.ArrayList<>();
        ClassCodeVisitorSupport visitor = new ClassCodeVisitorSupport() {
            @Override
            protected SourceUnit getSourceUnit() {
                return source;
            }

            @Override
            public void visitDeclarationExpression(DeclarationExpression d) {
                if (d.getLeftExpression() instanceof VariableExpression v) {
                    locals.add(v.getName());
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
        };
        visitor.visitClass(classNode);
        for (MethodCallExpression call : executes) {
            for (MapEntryExpression entry : namedArguments(call.getArguments())) {
                if (entry.getKeyExpression() instanceof ConstantExpression k && locals.contains(String.valueOf(k.getValue()))) {
                    String name = String.valueOf(k.getValue());
                    source.getErrorCollector().addErrorAndContinue(new SyntaxErrorMessage(new SyntaxException(
                            "execute: '" + name + "' is declared with 'def', so execute cannot see it: its keys name"
                            + " script variables. Expected an assignment without 'def', e.g. '" + name + " = pick { ... }'",
                            k.getLineNumber(), k.getColumnNumber()), source));
                }
            }
        }
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
