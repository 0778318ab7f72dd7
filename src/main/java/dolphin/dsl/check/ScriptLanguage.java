package dolphin.dsl.check;

import dolphin.dsl.vocabulary.Vocabulary;
import java.util.List;
import java.util.Set;

/**
 * What the checker knows of the language a script is written in.
 *
 * @param vocabulary every word and where it may be written
 * @param scriptClass the scripts' base class: its methods, Groovy's and Java's are the top-level names
 * @param wordClasses the platform's word classes: their {@code @Word} methods are top-level words too
 * @param categories the category classes active while scripts run: their getters are properties of numbers
 * @param presetVariables variables every run starts with (the engine's bindings)
 * @param callChecks checks of words' constant arguments that only the platform can make
 * @param wordsKnown whether every platform word is in the word classes: when an extension makes
 *                   words without naming their classes, a call nothing here answers may be one of
 *                   them, and is not reported
 */
public record ScriptLanguage(Vocabulary vocabulary, Class<?> scriptClass, List<Class<?>> wordClasses,
                             List<Class<?>> categories, Set<String> presetVariables, List<CallCheck> callChecks, boolean wordsKnown) {

    public ScriptLanguage {
        wordClasses = List.copyOf(wordClasses);
        categories = List.copyOf(categories);
        presetVariables = Set.copyOf(presetVariables);
        callChecks = List.copyOf(callChecks);
    }
}
