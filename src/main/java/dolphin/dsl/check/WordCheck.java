package dolphin.dsl.check;

import java.util.Comparator;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.control.messages.SyntaxErrorMessage;

/**
 * The check of every name in a script against the language, as a compilation step: after Groovy
 * has resolved classes, static imports and variable scopes (CANONICALIZATION), so that what is left
 * to look up is what the script's words, blocks and variables must answer. Each finding becomes a
 * compile error with its line and column; all of them are reported together.
 */
public final class WordCheck extends CompilationCustomizer {

    private final ScriptLanguage language;

    public WordCheck(ScriptLanguage language) {
        super(CompilePhase.CANONICALIZATION);
        this.language = language;
    }

    @Override
    public void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
        if (!classNode.isScript()) {
            return;
        }
        ScriptWalker.check(source, classNode, language).stream()
                .distinct()
                .sorted(Comparator.comparingInt(Finding::line).thenComparingInt(Finding::column))
                .forEach(f -> source.getErrorCollector().addErrorAndContinue(new SyntaxErrorMessage(
                        new FixableSyntaxException(f.message(), f.line(), f.column(), f.fixes()), source)));
    }
}
