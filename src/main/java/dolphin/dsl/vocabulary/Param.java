package dolphin.dsl.vocabulary;

/**
 * One parameter of a word's form.
 *
 * @param name the parameter's name in the source (class files keep them: -parameters)
 * @param type what the runtime accepts (Groovy's own conversions apply: a GString is a String)
 * @param unit its unit, or "" when it has none ({@link ParamUnits})
 * @param block the class whose words a closure parameter's block uses ({@code @DelegatesTo}), or null
 */
public record Param(String name, Class<?> type, String unit, Class<?> block) {

    public boolean isClosure() {
        return groovy.lang.Closure.class.isAssignableFrom(type);
    }

    /** How a form shows it: its name, a closure as {@code { name }}. */
    String shown() {
        return isClosure() ? "{ " + name + " }" : name;
    }
}
