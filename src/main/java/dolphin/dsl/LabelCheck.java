package dolphin.dsl;

import dolphin.dsl.check.QuickFix;
import dolphin.dsl.check.ScriptText;
import java.util.List;
import java.util.regex.Pattern;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.BinaryExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MapExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.ast.stmt.BlockStatement;
import org.codehaus.groovy.ast.stmt.ExpressionStatement;
import org.codehaus.groovy.ast.stmt.LoopingStatement;
import org.codehaus.groovy.ast.stmt.Statement;
import org.codehaus.groovy.control.SourceUnit;

/**
 * Finds a label on a statement that is no loop, as when an entry of {@code execute v1: a,} lost its
 * comma: Groovy ends the execute at the line break and reads the next line's {@code v2: b} as the
 * statement {@code b} labelled {@code v2}, which evaluates b and drops it; v2 gets no task and
 * nothing says so. A label names a loop for {@code break} and {@code continue} and does nothing
 * anywhere else. The fix adds the comma when the statement before takes named entries.
 */
final class LabelCheck extends ScriptCheck {

    @Override
    protected void check(SourceUnit source, ClassNode script) {
        ScriptText text = ScriptText.lazy(source);
        new Visitor(source) {
            @Override
            public void visitBlockStatement(BlockStatement block) {
                List<Statement> statements = block.getStatements();
                for (int i = 0; i < statements.size(); i++) {
                    Statement s = statements.get(i);
                    List<String> labels = s.getStatementLabels();
                    if (labels != null && !labels.isEmpty() && !(s instanceof LoopingStatement)) {
                        Statement before = i > 0 ? statements.get(i - 1) : null;
                        report(source, text, labels.get(labels.size() - 1), s, takesEntries(before) ? before : null);
                    }
                }
                super.visitBlockStatement(block);
            }
        }.visitClass(script);
    }

    private static void report(SourceUnit source, ScriptText text, String label, Statement labelled, Statement entries) {
        // the statement starts at what is labelled; the label is the last one before it on its line
        int at = text.between(labelled.getLineNumber(), 1, labelled.getLineNumber(), labelled.getColumnNumber()).lastIndexOf(label);
        int labelColumn = at >= 0 ? at + 1 : labelled.getColumnNumber();
        if (entries == null) {
            error(source, "'" + label + ":' is read as a label (Groovy's labels name loops for break and continue), so it"
                    + " does nothing here. Expected '" + label + " = value' to assign a variable, or the '" + label
                    + ": ...' entry on the line of the call it belongs to", labelled.getLineNumber(), labelColumn);
            return;
        }
        int line = entries.getLastLineNumber();
        int column = entries.getLastColumnNumber();
        boolean onlyBlanks = text.between(line, column, labelled.getLineNumber(), labelled.getColumnNumber())
                .matches("\\s*" + Pattern.quote(label) + "\\s*:\\s*");
        error(source, "'" + label + ":' is read as a label, not as an entry of the call on line " + line + ": that line does"
                + " not end with a comma, so Groovy ended the statement there, and this line's task is evaluated and"
                + " dropped. Expected a ',' at the end of line " + line, labelled.getLineNumber(), labelColumn,
                onlyBlanks ? new QuickFix[] {new QuickFix("Add the missing ',' at the end of line " + line, line, column, line, column, ",")}
                        : new QuickFix[0]);
    }

    /** Whether the statement is (or assigns) an execute, or a call with named entries. */
    private static boolean takesEntries(Statement s) {
        if (!(s instanceof ExpressionStatement es) || s.getLastLineNumber() < 1) {
            return false;
        }
        Expression e = es.getExpression();
        if (e instanceof BinaryExpression b && "=".equals(b.getOperation().getText())) {
            e = b.getRightExpression();
        }
        for (Expression link = e; link instanceof MethodCallExpression call; link = call.getObjectExpression()) {
            if (call.isImplicitThis() && "execute".equals(call.getMethodAsString())
                    || call.getArguments() instanceof TupleExpression t && t.getExpressions().stream().anyMatch(MapExpression.class::isInstance)) {
                return true;
            }
        }
        return false;
    }
}
