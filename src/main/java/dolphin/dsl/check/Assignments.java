package dolphin.dsl.check;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.DynamicVariable;
import org.codehaus.groovy.ast.Variable;
import org.codehaus.groovy.ast.expr.BinaryExpression;
import org.codehaus.groovy.ast.expr.DeclarationExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.syntax.Types;

/**
 * What a script assigns, read before checking it: the script variables (assigned without
 * {@code def}, anywhere: a closure may assign one that the script reads later) with the values given
 * them, and the {@code def} variables with their first value and whether they get another.
 */
final class Assignments {

    /** Script variables by name, each with every value assigned to it. */
    final Map<String, List<Expression>> scriptVariables = new LinkedHashMap<>();
    /** Local variables declared with a value. */
    final Map<Variable, Expression> declared = new IdentityHashMap<>();
    /** Local variables assigned again after their declaration. */
    final Set<Variable> reassigned = java.util.Collections.newSetFromMap(new IdentityHashMap<>());
    /** Whether the script reads or sets its variables through {@code binding}: which exist is then unknowable. */
    boolean usesBinding;
    /** Names first declared where a method of the script cannot see them, with their line: a hint for a mistake. */
    final Map<String, Integer> localLines = new LinkedHashMap<>();

    static Assignments of(SourceUnit source, ClassNode script) {
        Assignments a = new Assignments();
        new ClassCodeVisitorSupport() {
            @Override
            protected SourceUnit getSourceUnit() {
                return source;
            }

            @Override
            public void visitDeclarationExpression(DeclarationExpression d) {
                if (d.getLeftExpression() instanceof VariableExpression v) {
                    a.declared.put(v, d.getRightExpression());
                    a.localLines.putIfAbsent(v.getName(), d.getLineNumber());
                } else if (d.getLeftExpression() instanceof TupleExpression t) {
                    t.getExpressions().forEach(e -> a.localLines.putIfAbsent(e.getText(), d.getLineNumber()));
                }
                d.getRightExpression().visit(this);
            }

            @Override
            public void visitVariableExpression(VariableExpression v) {
                if ("binding".equals(v.getName()) && v.getAccessedVariable() instanceof DynamicVariable) {
                    a.usesBinding = true;
                }
            }

            @Override
            public void visitMethodCallExpression(MethodCallExpression call) {
                if ("getBinding".equals(call.getMethodAsString()) || "setBinding".equals(call.getMethodAsString())) {
                    a.usesBinding = true;
                }
                super.visitMethodCallExpression(call);
            }

            @Override
            public void visitBinaryExpression(BinaryExpression b) {
                if (Types.isAssignment(b.getOperation().getType())) {
                    targets(b.getLeftExpression()).forEach(v -> a.assigned(v, b.getRightExpression()));
                }
                super.visitBinaryExpression(b);
            }
        }.visitClass(script);
        return a;
    }

    private static List<VariableExpression> targets(Expression left) {
        List<VariableExpression> out = new ArrayList<>();
        if (left instanceof VariableExpression v) {
            out.add(v);
        } else if (left instanceof TupleExpression t) {
            t.getExpressions().stream().filter(VariableExpression.class::isInstance).map(VariableExpression.class::cast).forEach(out::add);
        }
        return out;
    }

    private void assigned(VariableExpression v, Expression value) {
        Variable target = v.getAccessedVariable();
        if (target == null || target instanceof DynamicVariable) {
            scriptVariables.computeIfAbsent(v.getName(), k -> new ArrayList<>()).add(value);
        } else {
            reassigned.add(target);
        }
    }

    Set<String> scriptVariableNames() {
        return new HashSet<>(scriptVariables.keySet());
    }
}
