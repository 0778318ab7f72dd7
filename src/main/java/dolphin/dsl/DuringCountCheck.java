package dolphin.dsl;

import dolphin.dsl.check.QuickFix;
import dolphin.dsl.check.ScriptText;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.ConstantExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MapExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;
import org.codehaus.groovy.control.SourceUnit;

/**
 * Finds {@code execute v: during 30 run t}: the command chain's words are paired from execute, so
 * Groovy reads {@code execute(v: during).30(run).t}, a call of a method named 30. Read from the
 * syntax tree where Groovy could build one. With a unit
 * ({@code during 30.seconds run t}) or another entry after it, Groovy cannot read it at all and says
 * "Unsupported command argument"; {@link #explain} says what that means there. The fix writes
 * {@code during(30) run t}.
 */
final class DuringCountCheck extends ScriptCheck {

    private static final String MESSAGE = "Groovy reads 'during %s run ...' after execute as more words of execute's own"
            + " command chain, execute(during).%s(run)..., since a chain pairs its words two by two from its first."
            + " Expected the duration in parentheses: 'during(%s) run ...'";
    /** "during 30 run", "during 2.minutes run": the words Groovy could not pair. */
    private static final Pattern WRITTEN = Pattern.compile("\\bduring\\s+([\\w.]+)\\s+run\\b");

    @Override
    protected void check(SourceUnit source, ClassNode script) {
        ScriptText text = ScriptText.lazy(source);
        new Visitor(source) {
            @Override
            public void visitMethodCallExpression(MethodCallExpression call) {
                String name = call.getMethod() instanceof ConstantExpression c ? String.valueOf(c.getValue()) : "";
                if (name.matches("\\d+(\\.\\d+)?") && call.getMethod() instanceof ConstantExpression count
                        && call.getObjectExpression() instanceof MethodCallExpression before && lastValue(before) instanceof VariableExpression during && "during".equals(during.getName())) {
                    String written = text.between(during.getLineNumber(), during.getColumnNumber(), count.getLastLineNumber(),
                            count.getLastColumnNumber());
                    QuickFix[] fixes = written.matches("during\\s+" + Pattern.quote(name))
                            ? new QuickFix[] {new QuickFix("Write 'during(" + name + ")'", during.getLineNumber(), during.getColumnNumber(),
                                    count.getLastLineNumber(), count.getLastColumnNumber(), "during(" + name + ")")}
                            : new QuickFix[0];
                    error(source, String.format(MESSAGE, name, name, name), during, fixes);
                }
                super.visitMethodCallExpression(call);
            }
        }.visitClass(script);
    }

    private static Expression lastValue(MethodCallExpression call) {
        List<Expression> args = arguments(call);
        Expression last = args.isEmpty() ? null : args.get(args.size() - 1);
        if (last instanceof MapExpression map && !map.getMapEntryExpressions().isEmpty()) {
            return map.getMapEntryExpressions().get(map.getMapEntryExpressions().size() - 1).getValueExpression();
        }
        return last;
    }

    /**
     * Groovy's "Unsupported command argument" on a line that holds {@code during N run}: the same
     * trap, where Groovy could not even pair the words (a unit, or an entry after it).
     */
    static Optional<ScriptError> explain(ScriptError error, String source) {
        if (!error.message().startsWith("Unsupported command argument") || error.line() < 1) {
            return Optional.empty();
        }
        String[] lines = source.split("\\R", -1);
        if (error.line() > lines.length) {
            return Optional.empty();
        }
        Matcher m = WRITTEN.matcher(lines[error.line() - 1]);
        if (!m.find()) {
            return Optional.empty();
        }
        String duration = m.group(1);
        int column = m.start() + 1;
        QuickFix fix = new QuickFix("Write 'during(" + duration + ")'", error.line(), column, error.line(), m.start(1) + duration.length() + 1,
                "during(" + duration + ")");
        return Optional.of(new ScriptError(error.file(), error.line(), column, String.format(MESSAGE, duration, duration, duration),
                List.of(fix)));
    }
}
