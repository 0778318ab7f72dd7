package dolphin.dsl;

import java.util.Map;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.ArgumentListExpression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.control.messages.SyntaxErrorMessage;
import org.codehaus.groovy.syntax.SyntaxException;

/**
 * Finds the second word of a two-word instruction at the start of a statement, as in the report's
 * Listings 2 and 3 where {@code then (...)} sits on the line below {@code waitFor { ... }}: Groovy
 * ends the statement at the line break, so {@code then} becomes a call of its own.
 */
final class SplitInstructionCheck extends CompilationCustomizer {

    /** Second word, and the first words it belongs to. */
    private static final Map<String, String> SECOND_WORDS = Map.of(
            "then", "waitFor { condition }' or 'when { condition }",
            "run", "until { condition }' or 'during ...",
            "onError", "watch task");

    SplitInstructionCheck() {
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
            public void visitMethodCallExpression(MethodCallExpression call) {
                String word = call.getMethodAsString();
                // Script's own run(File, String[]) takes two arguments; a split 'run task' has one
                if (call.isImplicitThis() && SECOND_WORDS.containsKey(word)
                        && !("run".equals(word) && arguments(call) != 1)) {
                    String opening = SECOND_WORDS.get(word);
                    source.getErrorCollector().addErrorAndContinue(new SyntaxErrorMessage(new SyntaxException(
                            "'" + word + "' begins a new statement: Groovy ended the statement before it at the line"
                            + " break, so the '" + opening + "' above did not get its '" + word + "' part. Expected '"
                            + word + "' on the same line as the end of '" + opening + "', with the rest of the task on"
                            + " the next lines if needed", call.getLineNumber(), call.getColumnNumber()), source));
                }
                super.visitMethodCallExpression(call);
            }
        }.visitClass(classNode);
    }

    private static int arguments(MethodCallExpression call) {
        return call.getArguments() instanceof TupleExpression t ? t.getExpressions().size()
                : call.getArguments() instanceof ArgumentListExpression a ? a.getExpressions().size() : 1;
    }
}
