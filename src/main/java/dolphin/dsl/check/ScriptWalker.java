package dolphin.dsl.check;

import dolphin.dsl.vocabulary.Suggestions;
import dolphin.dsl.vocabulary.Vocabulary;
import dolphin.dsl.vocabulary.WordScope;
import groovy.lang.Closure;
import groovy.lang.DelegatesTo;
import groovy.lang.MetaMethod;
import groovy.lang.MetaProperty;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.codehaus.groovy.ast.ASTNode;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.DynamicVariable;
import org.codehaus.groovy.ast.expr.ClosureExpression;
import org.codehaus.groovy.ast.expr.ConstantExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.PropertyExpression;
import org.codehaus.groovy.ast.expr.StaticMethodCallExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.runtime.InvokerHelper;

/**
 * Walks a compiled script and reports every name that will fail when the script runs: a word that
 * does not exist (with "did you mean"), a word called with arguments none of its forms takes, a
 * block's word used outside its block, a unit that does not exist, a variable never assigned. Only
 * what is certain is reported (docs/decisions.md, "Checking scripts").
 */
final class ScriptWalker extends ClassCodeVisitorSupport {

    /** Groovy's methods that call their closure with its delegate left as it is, the enclosing code's. */
    private static final Set<String> KEEPS_DELEGATE = Set.of("each", "eachWithIndex", "reverseEach", "collect",
            "collectMany", "collectEntries", "find", "findAll", "findResult", "findResults", "findIndexOf", "any",
            "every", "inject", "sum", "count", "groupBy", "countBy", "sort", "toSorted", "unique", "min", "max",
            "times", "upto", "downto", "step", "takeWhile", "dropWhile", "split", "forEach", "removeIf", "call",
            "eachLine", "withIndex", "collectNested", "eachPermutation", "eachCombination", "retainAll", "removeAll");

    /** "did you mean 'a' or 'b'?" in a platform's message, and each name in it. */
    private static final Pattern DID_YOU_MEAN = Pattern.compile("did you mean ((?:'[^']+'(?: or )?)+)\\?");
    private static final Pattern QUOTED = Pattern.compile("'([^']+)'");

    private final SourceUnit source;
    private final ClassNode script;
    private final ScriptLanguage language;
    private final Vocabulary vocabulary;
    private final Assignments assignments;
    private final Set<String> variables;
    private final ExpressionTypes types;
    private final Resolver resolver;
    private final FindingMessages messages;
    private final List<Finding> findings = new ArrayList<>();
    /** The call each argument was given to, for the fixes that rewrite a call around its argument. */
    private final Map<Expression, MethodCallExpression> callers = new IdentityHashMap<>();
    private final ScriptText text;
    private LookupFrame frame = LookupFrame.SCRIPT;

    private ScriptWalker(SourceUnit source, ClassNode script, ScriptLanguage language) {
        this.source = source;
        this.script = script;
        this.language = language;
        this.vocabulary = language.vocabulary();
        this.assignments = Assignments.of(source, script);
        this.variables = assignments.scriptVariableNames();
        variables.addAll(language.presetVariables());
        this.resolver = new Resolver(language, script, variables);
        this.types = new ExpressionTypes(language, assignments, resolver);
        this.messages = new FindingMessages(vocabulary, assignments, variables, script);
        this.text = ScriptText.lazy(source);
    }

    static List<Finding> check(SourceUnit source, ClassNode script, ScriptLanguage language) {
        ScriptWalker w = new ScriptWalker(source, script, language);
        w.visitClass(script);
        return w.findings;
    }

    @Override
    protected SourceUnit getSourceUnit() {
        return source;
    }

    // ---- calls

    @Override
    public void visitMethodCallExpression(MethodCallExpression call) {
        String name = call.getMethodAsString();
        if (name == null || call.getLineNumber() < 1) {
            super.visitMethodCallExpression(call);
            return;
        }
        List<Expression> args = ExpressionTypes.arguments(call.getArguments());
        boolean onThis = call.isImplicitThis()
                || call.getObjectExpression() instanceof VariableExpression v && v.isThisExpression();
        if (onThis) {
            Class<?>[] argTypes = types.of(args, frame);
            // this.x() is the script's own, even inside a block
            Resolution r = resolver.call(name, argTypes, call.isImplicitThis() ? frame : LookupFrame.SCRIPT);
            args.forEach(a -> callers.put(a, call));
            Class<?> held = heldGivenBlock(call);
            if (held != null) {
                // reported once, here; the block's words belong to a call Groovy does not make
                blockToValue(call, held);
                visitArguments(args, null, false);
                return;
            }
            if (args.stream().noneMatch(a -> a instanceof MethodCallExpression inner && heldGivenBlock(inner) != null)) {
                // with such an argument, what this call gets is the trap's doing: the finding is the trap's
                report(r, name, argTypes, call.getMethod(), args);
            }
            visitArguments(args, r.reach() == Resolution.Reach.METHOD ? Candidates.method(r.method()) : null,
                    r.reach() == Resolution.Reach.METHOD || r.reach() == Resolution.Reach.VARIABLE);
            return;
        }
        call.getObjectExpression().visit(this);
        Class<?> receiver = types.of(call.getObjectExpression(), frame);
        if (receiver != null && types.isChain(receiver)) {
            Class<?>[] argTypes = types.of(args, frame);
            List<MetaMethod> named = Candidates.all(receiver, name);
            MetaMethod m = Candidates.accepting(named, argTypes);
            if (m == null && argTypes.length > 0 && argTypes[0] == java.util.LinkedHashMap.class) {
                // execute v1: watch(t) onError { }, v2: t2: the entries after the second word come first, and the
                // method takes the arguments after them (onError's closure is its first parameter, an onError block)
                m = Candidates.accepting(named, Arrays.copyOfRange(argTypes, 1, argTypes.length));
                if (m != null) {
                    args.get(0).visit(this);
                    visitArguments(args.subList(1, args.size()), Candidates.method(m), true);
                    return;
                }
            }
            if (m == null) {
                chainMistake(receiver, name, named, argTypes, call.getMethod());
            }
            visitArguments(args, m == null ? null : Candidates.method(m), m != null);
            return;
        }
        visitArguments(args, null, KEEPS_DELEGATE.contains(name));
    }

    @Override
    public void visitStaticMethodCallExpression(StaticMethodCallExpression call) {
        List<Expression> args = ExpressionTypes.arguments(call.getArguments());
        Class<?> owner = ownerClass(call);
        if (owner == null || call.getLineNumber() < 1) {
            super.visitStaticMethodCallExpression(call);
            return;
        }
        Class<?>[] argTypes = types.of(args, frame);
        List<MetaMethod> named = Candidates.statics(owner, call.getMethod());
        MetaMethod m = Candidates.accepting(named, argTypes);
        if (m == null && !named.isEmpty()) {
            add(call, messages.wrongArguments(call.getMethod(), owner, named, argTypes, visibleScopes()));
        }
        visitArguments(args, m == null ? null : Candidates.method(m), m != null);
    }

    private static Class<?> ownerClass(StaticMethodCallExpression call) {
        try {
            return call.getOwnerType().redirect().getTypeClass();
        } catch (RuntimeException | LinkageError e) {
            return null;
        }
    }

    /**
     * Visits a call's arguments; a closure given to a parameter that names its builder
     * ({@code @DelegatesTo}) is a block of that builder's words, one given to a known method a plain
     * closure, any other one unknowable.
     */
    private void visitArguments(List<Expression> args, Method method, boolean known) {
        for (int i = 0; i < args.size(); i++) {
            Expression a = args.get(i);
            if (a instanceof ClosureExpression c) {
                Class<?> builder = method == null ? null : builder(method, i);
                LookupFrame inner = builder != null ? frame.block(builder) : known ? frame.plain() : frame.unknowable();
                within(inner, () -> c.getCode().visit(this));
            } else {
                a.visit(this);
            }
        }
    }

    private static Class<?> builder(Method method, int index) {
        if (index >= method.getParameterCount()) {
            return null;
        }
        DelegatesTo d = method.getParameters()[index].getAnnotation(DelegatesTo.class);
        return d == null || d.value() == DelegatesTo.Target.class ? null : d.value();
    }

    @Override
    public void visitClosureExpression(ClosureExpression c) {
        within(frame.plain(), () -> c.getCode().visit(this));
    }

    private void within(LookupFrame inner, Runnable body) {
        LookupFrame outer = frame;
        frame = inner;
        try {
            body.run();
        } finally {
            frame = outer;
        }
    }

    // ---- names read as values

    @Override
    public void visitVariableExpression(VariableExpression v) {
        if (v.getLineNumber() < 1 || !(v.getAccessedVariable() instanceof DynamicVariable) || v.isThisExpression()
                || v.isSuperExpression() || variables.contains(v.getName()) || assignments.usesBinding) {
            return;
        }
        String name = v.getName();
        for (LookupFrame f = frame; f != null; f = f.outer()) {
            if (f.unknown()) {
                return;
            }
            if (f.block() != null && hasProperty(f.block(), name)) {
                return;
            }
        }
        if (hasProperty(language.scriptClass(), name) || frame.outer() != null && hasProperty(Closure.class, name)) {
            return;
        }
        add(v, name, messages.unknownName(name, visibleScopes()));
    }

    private static boolean hasProperty(Class<?> type, String name) {
        MetaProperty p = InvokerHelper.getMetaClass(type).getMetaProperty(name);
        return p != null;
    }

    @Override
    public void visitPropertyExpression(PropertyExpression p) {
        super.visitPropertyExpression(p);
        String name = p.getPropertyAsString();
        if (name == null || p.getLineNumber() < 1 || p.isSpreadSafe()) {
            return;
        }
        Class<?> receiver = types.of(p.getObjectExpression(), frame);
        if (ExpressionTypes.isNumber(receiver) && !vocabulary.units().words().containsKey(name)
                && !hasProperty(receiver, name) && !isCategoryProperty(name)) {
            add(p.getProperty(), name, messages.unknownUnit(name));
        }
    }

    /** A getter of a category: a unit an extension adds without describing it. */
    private boolean isCategoryProperty(String name) {
        String getter = "get" + Character.toUpperCase(name.charAt(0)) + name.substring(1);
        return language.categories().stream().flatMap(c -> Arrays.stream(c.getMethods()))
                .anyMatch(m -> m.getName().equals(getter) && m.getParameterCount() == 1
                        && java.lang.reflect.Modifier.isStatic(m.getModifiers()));
    }

    // ---- messages

    private void report(Resolution r, String name, Class<?>[] argTypes, ASTNode at, List<Expression> args) {
        switch (r.reach()) {
            case WRONG_ARGUMENTS -> add(at, messages.wrongArguments(name, r.owner(), r.named(), argTypes, visibleScopes()));
            case MISSING -> add(at, name, messages.missing(name, visibleScopes()));
            case METHOD -> callChecks(name, r, at, args);
            default -> {
            }
        }
    }

    private void callChecks(String name, Resolution r, ASTNode at, List<Expression> args) {
        if (!language.wordClasses().contains(r.owner())) {
            return;
        }
        List<Object> constants = args.stream()
                .map(a -> a instanceof ConstantExpression c && c.getValue() != null ? c.getValue() : CallCheck.UNKNOWN)
                .toList();
        for (CallCheck check : language.callChecks()) {
            String mistake = check.mistake(name, constants);
            if (mistake != null) {
                findings.add(new Finding(at.getLineNumber(), at.getColumnNumber(), mistake, textFixes(mistake, args)));
            }
        }
    }

    /**
     * A platform's "did you mean 'SMOKE'?" about a text argument ({@code sensor(v, 'SMOKY')}): each name
     * it suggests that is near a text argument replaces that text, where the argument is written as a
     * plain quoted text.
     */
    private List<QuickFix> textFixes(String mistake, List<Expression> args) {
        Matcher said = DID_YOU_MEAN.matcher(mistake);
        if (!said.find()) {
            return List.of();
        }
        List<String> meant = new ArrayList<>();
        Matcher quoted = QUOTED.matcher(said.group(1));
        while (quoted.find()) {
            meant.add(quoted.group(1));
        }
        List<QuickFix> fixes = new ArrayList<>();
        for (Expression a : args) {
            if (!(a instanceof ConstantExpression c) || !(c.getValue() instanceof String written) || c.getLineNumber() != c.getLastLineNumber()) {
                continue;
            }
            String literal = text.between(c.getLineNumber(), c.getColumnNumber(), c.getLastLineNumber(), c.getLastColumnNumber());
            if (literal.length() < 2 || !literal.substring(1, literal.length() - 1).equals(written) || "'\"".indexOf(literal.charAt(0)) < 0) {
                continue;
            }
            for (String m : meant) {
                if (!Suggestions.near(written, List.of(m)).isEmpty()) {
                    fixes.add(QuickFix.rename(c.getLineNumber(), c.getColumnNumber() + 1, written, m));
                }
            }
        }
        return fixes;
    }

    /**
     * {@code move homePos { north 30 }}: Groovy gives a block to the name right before it, so this is
     * {@code move(homePos({ north 30 }))}, a call of the variable. Reported when the variable surely
     * holds something that takes no block (a position, a task); the fix writes {@code move(homePos) { ... }}.
     */
    private void blockToValue(MethodCallExpression call, Class<?> held) {
        String name = call.getMethodAsString();
        List<Expression> args = ExpressionTypes.arguments(call.getArguments());
        ClosureExpression block = (ClosureExpression) args.get(args.size() - 1);
        MethodCallExpression caller = callers.get(call);
        String callerName = caller == null || !caller.isImplicitThis() ? null : caller.getMethodAsString();
        String expected = callerName == null ? "the variable in parentheses, e.g. 'move(" + name + ") { ... }'"
                : "'" + callerName + "(" + name + ") { ... }'";
        String message = "'" + name + " { ... }' gives the block to " + name + ", which holds a " + held.getSimpleName()
                + ", not a command: Groovy hands a block to the name right before it"
                + (callerName == null ? "" : ", not to '" + callerName + "'") + ". Expected " + expected;
        List<QuickFix> fixes = new ArrayList<>();
        if (callerName != null && ExpressionTypes.arguments(caller.getArguments()).size() == 1) {
            Expression callerWord = caller.getMethod();
            String between = text.between(callerWord.getLastLineNumber(), callerWord.getLastColumnNumber(),
                    block.getLineNumber(), block.getColumnNumber());
            if (between.matches("[ \\t]+" + Pattern.quote(name) + "[ \\t]*")) {
                fixes.add(new QuickFix("Write '" + callerName + "(" + name + ") { ... }'", callerWord.getLastLineNumber(),
                        callerWord.getLastColumnNumber(), block.getLineNumber(), block.getColumnNumber(), "(" + name + ") "));
            }
        }
        findings.add(new Finding(call.getLineNumber(), call.getColumnNumber(), message, fixes));
    }

    /** The class of what a variable called with a block holds, when it surely takes no block; else null. */
    private Class<?> heldGivenBlock(MethodCallExpression call) {
        List<Expression> args = ExpressionTypes.arguments(call.getArguments());
        if (!call.isImplicitThis() || call.getMethodAsString() == null || args.isEmpty()
                || !(args.get(args.size() - 1) instanceof ClosureExpression)
                || resolver.call(call.getMethodAsString(), types.of(args, frame), frame).reach() != Resolution.Reach.VARIABLE) {
            return null;
        }
        Class<?> held = types.of(new VariableExpression(call.getMethodAsString()), frame);
        return held == null || Closure.class.isAssignableFrom(held) || !Candidates.all(held, "call").isEmpty() ? null : held;
    }

    private void chainMistake(Class<?> receiver, String name, List<MetaMethod> named, Class<?>[] argTypes, ASTNode at) {
        if (named.isEmpty()) {
            add(at, name, messages.wrongFollower(vocabulary.scopeOf(receiver).orElseThrow(), name));
        } else {
            add(at, messages.wrongArguments(name, receiver, named, argTypes, visibleScopes()));
        }
    }

    /** The scopes whose words a name here reaches: the enclosing blocks, innermost first, then the script. */
    private List<WordScope> visibleScopes() {
        List<WordScope> scopes = new ArrayList<>();
        for (LookupFrame f = frame; f != null; f = f.outer()) {
            if (f.block() != null) {
                vocabulary.scopeOf(f.block()).ifPresent(scopes::add);
            }
        }
        scopes.add(vocabulary.script());
        return scopes;
    }

    private void add(ASTNode at, String message) {
        findings.add(new Finding(at.getLineNumber(), at.getColumnNumber(), message, List.of()));
    }

    /** A finding on a wrong name, written at {@code at}: each name it suggests instead is a fix. */
    private void add(ASTNode at, String name, FindingText said) {
        findings.add(new Finding(at.getLineNumber(), at.getColumnNumber(), said.message(), said.meant().stream()
                .map(meant -> QuickFix.rename(at.getLineNumber(), at.getColumnNumber(), name, meant)).toList()));
    }
}
