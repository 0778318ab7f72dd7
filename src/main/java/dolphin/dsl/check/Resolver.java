package dolphin.dsl.check;

import groovy.lang.MetaMethod;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
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
        // every place the name may be answered, in the order Groovy asks them
        List<Resolution> places = new ArrayList<>();
        for (LookupFrame f = frame; f != null; f = f.outer()) {
            if (f.unknown()) {
                // a block inside it may still answer; beyond it nothing can be known
                return firstAnswer(places).orElse(Resolution.UNKNOWABLE);
            }
            if (f.block() != null) {
                places.add(fit(f.block(), Candidates.all(f.block(), name), arguments));
            }
        }
        if (script.getDeclaredMethods(name).stream().anyMatch(m -> m.getLineNumber() > 0)) {
            places.add(Resolution.SCRIPT_METHOD);
        }
        places.add(fit(language.scriptClass(), Candidates.all(language.scriptClass(), name), arguments));
        for (Class<?> words : language.wordClasses()) {
            places.add(fit(words, Candidates.words(words, name), arguments));
        }
        if (variables.contains(name)) {
            places.add(Resolution.VARIABLE);
        }
        Optional<Resolution> answer = firstAnswer(places);
        if (answer.isPresent()) {
            return answer.get();
        }
        if (!language.wordsKnown()) {
            return Resolution.UNKNOWABLE;
        }
        return places.stream().filter(r -> r.reach() == Resolution.Reach.WRONG_ARGUMENTS).findFirst()
                .orElse(Resolution.MISSING);
    }

    private static Optional<Resolution> firstAnswer(List<Resolution> places) {
        return places.stream().filter(Resolution::answers).findFirst();
    }

    /** The owner's methods of the name: the one that takes these arguments, or those that do not, or none. */
    private static Resolution fit(Class<?> owner, List<MetaMethod> named, Class<?>[] arguments) {
        MetaMethod m = Candidates.accepting(named, arguments);
        return m != null ? Resolution.method(m, owner) : named.isEmpty() ? Resolution.MISSING : Resolution.wrong(owner, named);
    }
}
