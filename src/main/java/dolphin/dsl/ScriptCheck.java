package dolphin.dsl;

import dolphin.dsl.check.FixableSyntaxException;
import dolphin.dsl.check.QuickFix;
import java.util.List;
import org.codehaus.groovy.ast.ASTNode;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.control.messages.SyntaxErrorMessage;

/**
 * A compile-time check of a script's code as Groovy parsed it (CONVERSION phase: before names are
 * resolved), for layouts that Groovy reads differently from what the user meant. Problems become
 * compile errors with line and column, so `dolphin check` finds them without running anything.
 */
abstract class ScriptCheck extends CompilationCustomizer {

    ScriptCheck() {
        super(CompilePhase.CONVERSION);
    }

    @Override
    public final void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
        if (classNode.isScript()) {
            check(source, classNode);
        }
    }

    protected abstract void check(SourceUnit source, ClassNode script);

    /** A visitor of the script's code; subclasses override the visit methods they need. */
    abstract static class Visitor extends ClassCodeVisitorSupport {
        private final SourceUnit source;

        Visitor(SourceUnit source) {
            this.source = source;
        }

        @Override
        protected SourceUnit getSourceUnit() {
            return source;
        }
    }

    /** A call's arguments as a list: named arguments are one map, first. */
    static List<Expression> arguments(MethodCallExpression call) {
        return call.getArguments() instanceof TupleExpression t ? t.getExpressions() : List.of(call.getArguments());
    }

    static void error(SourceUnit source, String message, ASTNode at, QuickFix... fixes) {
        error(source, message, at.getLineNumber(), at.getColumnNumber(), fixes);
    }

    static void error(SourceUnit source, String message, int line, int column, QuickFix... fixes) {
        source.getErrorCollector().addErrorAndContinue(new SyntaxErrorMessage(
                new FixableSyntaxException(message, line, column, List.of(fixes)), source));
    }
}
