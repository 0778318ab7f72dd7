package dolphin.dsl;

import org.codehaus.groovy.ast.ASTNode;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.control.messages.SyntaxErrorMessage;
import org.codehaus.groovy.syntax.SyntaxException;

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

    static void error(SourceUnit source, String message, ASTNode at) {
        source.getErrorCollector().addErrorAndContinue(new SyntaxErrorMessage(
                new SyntaxException(message, at.getLineNumber(), at.getColumnNumber()), source));
    }
}
