package dolphin.dsl.vocabulary;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks a public method as a word of the Dolphin language and describes it in one line. The
 * {@link Vocabulary} reads the words, their forms and the blocks they open from the methods
 * themselves, so what the checker, the editor support and the listings know is what the runtime
 * calls (docs/editors.md, "One vocabulary").
 */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface Word {

    /** One line: what the word does, with its units; shown in completion, hover and listings. */
    String value();
}
