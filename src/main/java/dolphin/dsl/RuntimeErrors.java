package dolphin.dsl;

import dolphin.dsl.vocabulary.Suggestions;
import groovy.lang.MissingMethodException;
import groovy.lang.MissingPropertyException;
import java.util.Arrays;
import java.util.Collection;
import java.util.stream.Collectors;
import org.codehaus.groovy.runtime.typehandling.GroovyCastException;

/** Turns an exception thrown while a script runs into a {@link ScriptError}: the script's line and what was expected. */
final class RuntimeErrors {

    private RuntimeErrors() {
    }

    static ScriptError describe(Throwable t, String file, Collection<String> words, Collection<String> variables) {
        return new ScriptError(file, line(t, ScriptCompiler.codeName(file)), 0, message(t, words, variables));
    }

    /** The innermost script line in the exception's chain of stack traces. */
    static int line(Throwable t, String codeName) {
        for (Throwable c = t; c != null; c = c.getCause()) {
            for (StackTraceElement e : c.getStackTrace()) {
                if (codeName.equals(e.getFileName()) && e.getLineNumber() > 0) {
                    return e.getLineNumber();
                }
            }
        }
        return 0;
    }

    static String message(Throwable t, Collection<String> words, Collection<String> variables) {
        if (t instanceof MissingMethodException m && OPERATORS.containsKey(m.getMethod()) && m.getType() != null
                && m.getArguments() != null && m.getArguments().length == 1) {
            Object arg = m.getArguments()[0];
            return "the operator '" + OPERATORS.get(m.getMethod()) + "' does not apply to " + m.getType().getSimpleName()
                    + " and " + (arg == null ? "null" : arg.getClass().getSimpleName())
                    + ": expected tasks with >> and |, a task and a condition closure with /, a task and a vehicle set"
                    + " with [ ], vehicle sets with + - &, a vehicle set and a closure with |, a position and a radius with ^";
        }
        if (t instanceof MissingMethodException m && words.contains(m.getMethod())) {
            return "wrong arguments for '" + m.getMethod() + "': got " + types(m.getArguments()) + accepted(m);
        }
        if (t instanceof MissingMethodException m) {
            return "unknown command '" + m.getMethod() + "'" + arguments(m.getArguments())
                    + Suggestions.didYouMean(m.getMethod(), words) + ". Expected a DSL word, a Groovy method or a closure variable.";
        }
        if (t instanceof MissingPropertyException p) {
            if ("execute".equals(p.getProperty())) {
                return "'execute' has no task: expected 'execute task' or 'execute v1: task1, v2: task2' on one line";
            }
            if (words.contains(p.getProperty())) {
                return "'" + p.getProperty() + "' is a command, but Groovy read it as a variable here. Expected it with"
                        + " its arguments, e.g. '" + p.getProperty() + "()', and in parentheses when it is the argument of"
                        + " another command, e.g. 'execute(during(10) run task)'";
            }
            return "unknown name '" + p.getProperty() + "'" + Suggestions.didYouMean(p.getProperty(), variables)
                    + ". Expected a variable assigned earlier in the script (names are case-sensitive)";
        }
        if (t instanceof GroovyCastException c) {
            return "wrong argument type: " + c.getMessage();
        }
        if (t instanceof DslException || t instanceof dolphin.core.EnvironmentException) {
            return t.getMessage();
        }
        return t.getClass().getSimpleName() + (t.getMessage() == null ? "" : ": " + t.getMessage());
    }

    /** "; expected (Number)" from the public methods of that name, if the class has any. */
    private static String accepted(MissingMethodException m) {
        if (m.getType() == null) {
            return "";
        }
        String forms = Arrays.stream(m.getType().getMethods())
                .filter(x -> x.getName().equals(m.getMethod()))
                .map(x -> Arrays.stream(x.getParameterTypes()).map(Class::getSimpleName).collect(Collectors.joining(", ", "(", ")")))
                .distinct()
                .sorted()
                .collect(Collectors.joining(" or "));
        return forms.isEmpty() ? "" : "; expected " + forms;
    }

    private static String arguments(Object[] args) {
        return " with arguments " + types(args);
    }

    private static String types(Object[] args) {
        return Arrays.stream(args == null ? new Object[0] : args)
                .map(a -> a == null ? "null" : a.getClass().getSimpleName())
                .collect(Collectors.joining(", ", "(", ")"));
    }

    /** Groovy's operator methods and how scripts write them. */
    private static final java.util.Map<String, String> OPERATORS = java.util.Map.of(
            "rightShift", ">>", "or", "|", "div", "/", "getAt", "[ ]", "plus", "+", "minus", "-", "and", "&", "xor", "^");

}
