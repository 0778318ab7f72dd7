package dolphin.dsl.check;

import groovy.lang.MetaMethod;
import java.util.List;
import java.util.Set;
import org.codehaus.groovy.ast.ClassNode;

/**
 * Finds what a call without a receiver reaches at run time, as Groovy looks it up: the builders of
 * the enclosing blocks, innermost first, then the script (its own methods, its base class with
 * Groovy's methods, the platform's words, a script variable holding a closure).
 */
final class Resolver {

    private final ScriptLanguage language;
    private final ClassNode script;
    private final Set<String> variables;

    Resolver(ScriptLanguage language, ClassNode script, Set<String> variables) {
        this.language = language;
        this.script = script;
        this.variables = variables;
    }

    Resolution call(String name, Class<?>[] arguments, LookupFrame frame) {
        Resolution wrong = null;
        for (LookupFrame f = frame; f != null; f = f.outer()) {
            if (f.unknown()) {
                return Resolution.UNKNOWABLE;
            }
            if (f.block() != null) {
                List<MetaMethod> named = Candidates.all(f.block(), name);
                MetaMethod m = Candidates.accepting(named, arguments);
                if (m != null) {
                    return Resolution.method(m, f.block());
                }
                if (!named.isEmpty() && wrong == null) {
                    wrong = Resolution.wrong(f.block(), named);
                }
            }
        }
        if (script.getDeclaredMethods(name).stream().anyMatch(m -> m.getLineNumber() > 0)) {
            return Resolution.SCRIPT_METHOD;
        }
        List<MetaMethod> base = Candidates.all(language.scriptClass(), name);
        MetaMethod m = Candidates.accepting(base, arguments);
        if (m != null) {
            return Resolution.method(m, language.scriptClass());
        }
        if (!base.isEmpty() && wrong == null) {
            wrong = Resolution.wrong(language.scriptClass(), base);
        }
        for (Class<?> words : language.wordClasses()) {
            List<MetaMethod> named = Candidates.words(words, name);
            m = Candidates.accepting(named, arguments);
            if (m != null) {
                return Resolution.method(m, words);
            }
            if (!named.isEmpty() && wrong == null) {
                wrong = Resolution.wrong(words, named);
            }
        }
        if (variables.contains(name)) {
            return Resolution.VARIABLE;
        }
        if (!language.wordsKnown()) {
            return Resolution.UNKNOWABLE;
        }
        return wrong != null ? wrong : Resolution.MISSING;
    }
}
