package dolphin.dsl;

import java.util.Map;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.BinaryExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.control.messages.SyntaxErrorMessage;
import org.codehaus.groovy.syntax.SyntaxException;

/**
 * Finds {@code execute (a >> b) / { c }}: a parenthesis right after {@code execute} holds its whole
 * argument list for Groovy, so the operator after it applies to what execute returned, once the
 * task has already run without it. The constraint (or sequence, or vehicles) would be lost.
 */
final class ExecuteOperandCheck extends CompilationCustomizer {

    private static final Map<String, String> OPERATORS = Map.of("/", "/ { condition }", ">>", ">> task", "|", "| task",
            "[", "[vehicles]");

    ExecuteOperandCheck() {
        super(CompilePhase.CONVERSION);
    }

    @Override
    public void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
        if (!classNode.isScript()) {
            return;
        }
        new ClassCodeVisitorSupport() {
            @Override
            protected SourceUnit getSourceUnit() {
                return source;
            }

            @Override
            public void visitBinaryExpression(BinaryExpression b) {
                String op = b.getOperation().getText();
                if (OPERATORS.containsKey(op) && b.getLeftExpression() instanceof MethodCallExpression call
                        && call.isImplicitThis() && "execute".equals(call.getMethodAsString())) {
                    String rest = OPERATORS.get(op);
                    source.getErrorCollector().addErrorAndContinue(new SyntaxErrorMessage(new SyntaxException(
                            "execute: Groovy takes the parentheses after 'execute' as its whole argument list, so '"
                            + rest + "' would apply to execute's result after the task ran without it. Expected the"
                            + " whole task inside execute's parentheses, e.g. 'execute((a >> b) " + rest + ")', or no"
                            + " parenthesis right after execute: 'execute _: (a >> b) " + rest + "'",
                            call.getLineNumber(), call.getColumnNumber()), source));
                }
                super.visitBinaryExpression(b);
            }
        }.visitClass(classNode);
    }
}
