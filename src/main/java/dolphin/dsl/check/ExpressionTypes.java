package dolphin.dsl.check;

import dolphin.dsl.vocabulary.WordScope;
import groovy.lang.Closure;
import groovy.lang.GString;
import groovy.lang.MetaMethod;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Set;
import org.codehaus.groovy.ast.ClassHelper;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.DynamicVariable;
import org.codehaus.groovy.ast.Variable;
import org.codehaus.groovy.ast.expr.CastExpression;
import org.codehaus.groovy.ast.expr.ClosureExpression;
import org.codehaus.groovy.ast.expr.ConstantExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.GStringExpression;
import org.codehaus.groovy.ast.expr.ListExpression;
import org.codehaus.groovy.ast.expr.MapExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.NamedArgumentListExpression;
import org.codehaus.groovy.ast.expr.PropertyExpression;
import org.codehaus.groovy.ast.expr.StaticMethodCallExpression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.ast.expr.UnaryMinusExpression;
import org.codehaus.groovy.ast.expr.UnaryPlusExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;

/**
 * The class of an expression's value where it is certain before the script runs: literals, a word's
 * result ({@code pos { }} is a Position, {@code pick { }} a vehicle set), {@code 10.minutes}, and
 * variables whose every value is such an expression. Anything else is unknown (null), and an
 * unknown argument fits every parameter: the checker never guesses.
 */
final class ExpressionTypes {

    private final ScriptLanguage language;
    private final Assignments assignments;
    private final Resolver resolver;
    /** Script variables whose type is being worked out: a = b; b = a is unknown, not endless. */
    private final Set<String> pending = new HashSet<>();

    ExpressionTypes(ScriptLanguage language, Assignments assignments, Resolver resolver) {
        this.language = language;
        this.assignments = assignments;
        this.resolver = resolver;
    }

    /** The arguments of a call as a list: named arguments are one map, first. */
    static List<Expression> arguments(Expression args) {
        List<Expression> out = new ArrayList<>();
        if (args instanceof TupleExpression t) {
            for (Expression e : t.getExpressions()) {
                out.add(e);
            }
        } else if (args != null) {
            out.add(args);
        }
        return out;
    }

    Class<?>[] of(List<Expression> expressions, LookupFrame frame) {
        return expressions.stream().map(e -> of(e, frame)).toArray(Class<?>[]::new);
    }

    Class<?> of(Expression e, LookupFrame frame) {
        if (e instanceof ConstantExpression c) {
            return c.getValue() == null ? null : c.getValue().getClass();
        }
        if (e instanceof GStringExpression) {
            return GString.class;
        }
        if (e instanceof ClosureExpression) {
            return Closure.class;
        }
        if (e instanceof MapExpression || e instanceof NamedArgumentListExpression) {
            return LinkedHashMap.class;
        }
        if (e instanceof ListExpression) {
            return ArrayList.class;
        }
        if (e instanceof UnaryMinusExpression u) {
            return number(of(u.getExpression(), frame));
        }
        if (e instanceof UnaryPlusExpression u) {
            return number(of(u.getExpression(), frame));
        }
        if (e instanceof CastExpression c) {
            return loaded(c.getType());
        }
        if (e instanceof PropertyExpression p && isNumber(of(p.getObjectExpression(), frame))
                && language.vocabulary().units().words().containsKey(p.getPropertyAsString())) {
            return Double.class;
        }
        if (e instanceof StaticMethodCallExpression s) {
            Class<?> owner = loaded(s.getOwnerType());
            if (owner == null) {
                return null;
            }
            List<Expression> args = arguments(s.getArguments());
            return result(Candidates.accepting(Candidates.statics(owner, s.getMethod()), of(args, frame)));
        }
        if (e instanceof MethodCallExpression m && m.getMethodAsString() != null) {
            return call(m, frame);
        }
        if (e instanceof VariableExpression v) {
            return variable(v, frame);
        }
        return null;
    }

    private Class<?> call(MethodCallExpression m, LookupFrame frame) {
        Class<?>[] args = of(arguments(m.getArguments()), frame);
        if (m.isImplicitThis()) {
            Resolution r = resolver.call(m.getMethodAsString(), args, frame);
            if (r.reach() != Resolution.Reach.METHOD) {
                return null;
            }
            Class<?> type = result(r.method());
            return type != null ? type : pendingHalf(arguments(m.getArguments()), frame);
        }
        Class<?> receiver = of(m.getObjectExpression(), frame);
        if (receiver != null && isChain(receiver)) {
            return result(Candidates.accepting(Candidates.all(receiver, m.getMethodAsString()), args));
        }
        return null;
    }

    /**
     * The first half of a two-word instruction given to a word that returns no type of its own:
     * {@code execute v: waitFor { c } then t} reads as {@code execute(v: waitFor { c }).then(t)}, and
     * what follows execute is waitFor's second word. Null when no argument (or named argument) is one.
     */
    private Class<?> pendingHalf(List<Expression> args, LookupFrame frame) {
        List<Expression> values = new ArrayList<>();
        for (Expression a : args) {
            if (a instanceof MapExpression map) {
                map.getMapEntryExpressions().forEach(e -> values.add(e.getValueExpression()));
            } else {
                values.add(a);
            }
        }
        List<Class<?>> halves = new ArrayList<>();
        values.stream().map(v -> of(v, frame)).filter(t -> t != null && isChain(t)).distinct().forEach(halves::add);
        return halves.size() == 1 ? halves.get(0) : null;
    }

    /** Whether the class holds the second words of two-word instructions ({@code then} after {@code waitFor}). */
    boolean isChain(Class<?> type) {
        return language.vocabulary().scopeOf(type).map(s -> s.kind() == WordScope.ScopeKind.CHAIN).orElse(false);
    }

    private Class<?> variable(VariableExpression v, LookupFrame frame) {
        Variable target = v.getAccessedVariable();
        if (target == null || target instanceof DynamicVariable) {
            List<Expression> values = assignments.scriptVariables.get(v.getName());
            if (values == null || !pending.add(v.getName())) {
                return null;
            }
            try {
                Class<?> type = null;
                for (Expression value : values) {
                    Class<?> t = of(value, LookupFrame.SCRIPT);
                    if (t == null || (type != null && type != t)) {
                        return null;
                    }
                    type = t;
                }
                return type;
            } finally {
                pending.remove(v.getName());
            }
        }
        if (!target.isDynamicTyped() && target.getOriginType() != null) {
            Class<?> declared = loaded(target.getOriginType());
            if (declared != null && declared != Object.class) {
                return declared;
            }
        }
        Expression initial = assignments.declared.get(target);
        if (initial == null || assignments.reassigned.contains(target)) {
            return null;
        }
        return of(initial, frame);
    }

    private static Class<?> result(MetaMethod m) {
        if (m == null) {
            return null;
        }
        Class<?> r = m.getReturnType();
        if (r == Object.class || r == void.class) {
            return null;
        }
        return r.isPrimitive() ? ClassHelper.getWrapper(ClassHelper.make(r)).getTypeClass() : r;
    }

    private static Class<?> loaded(ClassNode node) {
        try {
            if (!node.isResolved()) {
                return null;
            }
            ClassNode type = ClassHelper.isPrimitiveType(node) ? ClassHelper.getWrapper(node) : node;
            return type.redirect().getTypeClass();
        } catch (RuntimeException | LinkageError e) {
            return null;
        }
    }

    static boolean isNumber(Class<?> type) {
        return type != null && Number.class.isAssignableFrom(type);
    }

    private static Class<?> number(Class<?> type) {
        return isNumber(type) ? type : null;
    }
}
