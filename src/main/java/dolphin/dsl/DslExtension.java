package dolphin.dsl;

import dolphin.dsl.check.CallCheck;
import java.util.List;
import org.codehaus.groovy.control.customizers.ImportCustomizer;

/**
 * The plug-in point through which a platform extends the script language. A {@code Platform} that
 * also implements this interface is picked up by the {@link Engine}; other extensions can be added
 * with {@link Engine#addExtension}.
 *
 * <p>Nothing here changes Groovy globally: imports apply to Dolphin scripts only, words are
 * resolved by the scripts' base class, and categories are active on the script thread while a
 * script runs.
 */
public interface DslExtension {

    /** Adds imports to every script, e.g. static-star imports of builder methods or message packages. */
    default void addImports(ImportCustomizer imports) {
    }

    /**
     * Objects whose public methods scripts may call as DSL words, made for each script run. A word
     * defined by the core language takes precedence.
     */
    default List<Object> words(ScriptContext context) {
        return List.of();
    }

    /**
     * The classes of the objects {@link #words} makes and those whose static methods
     * {@link #addImports} imports, read for the language's {@link dolphin.dsl.vocabulary.Vocabulary}.
     * An extension that makes words but does not name their classes here leaves the check unable to
     * tell an unknown word from one of its own, so it reports none.
     */
    default List<Class<?>> wordClasses() {
        return List.of();
    }

    /** Checks of calls to this extension's words whose arguments are constants, made before the script runs. */
    default List<CallCheck> callChecks() {
        return List.of();
    }

    /** Groovy category classes (e.g. extra units) active while a script runs. */
    default List<Class<?>> categories() {
        return List.of();
    }
}
