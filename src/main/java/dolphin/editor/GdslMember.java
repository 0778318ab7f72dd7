package dolphin.editor;

import dolphin.dsl.vocabulary.Param;
import dolphin.dsl.vocabulary.Signature;
import dolphin.dsl.vocabulary.WordEntry;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Collectors;

/**
 * One word as GDSL declares it: a {@code method} line for each of its forms, or a {@code property}
 * line for a unit, with the types, the parameter names and the word's line as documentation.
 */
final class GdslMember {

    /** The type of every unit: the category's getters return double ({@code dolphin.dsl.Units}). */
    private static final String UNIT_TYPE = "double";

    private GdslMember() {
    }

    /** One {@code method} line per form, the shortest first, so that the file reads the same on every build. */
    static List<String> methods(WordEntry word) {
        return word.signatures().stream()
                .sorted(Comparator.comparingInt((Signature s) -> s.params().size()).thenComparing(GdslMember::params))
                .map(s -> "method name: " + literal(word.name()) + ", type: " + literal(typeName(s.returns()))
                        + ", params: " + params(s) + ", doc: " + literal(doc(word.description(), s.params())))
                .toList();
    }

    static String property(WordEntry unit) {
        return "property name: " + literal(unit.name()) + ", type: " + literal(UNIT_TYPE)
                + ", doc: " + literal(doc(unit.description(), List.of()));
    }

    /** The parameters as GDSL's map of name to type; {@code [:]} for none. */
    private static String params(Signature s) {
        if (s.params().isEmpty()) {
            return "[:]";
        }
        return s.params().stream().map(p -> p.name() + ": " + literal(typeName(p.type())))
                .collect(Collectors.joining(", ", "[", "]"));
    }

    /**
     * The word's line and the units of its parameters, but for those named after their unit
     * ({@code lat(degrees)}); IntelliJ shows it as HTML.
     */
    private static String doc(String description, List<Param> params) {
        String units = params.stream().filter(p -> !p.unit().isEmpty() && !p.unit().equals(p.name()))
                .map(p -> p.name() + ": " + p.unit())
                .collect(Collectors.joining(", "));
        return html(description) + (units.isEmpty() ? "" : "<br>" + html(units));
    }

    /**
     * The name IntelliJ reads a type by: nested classes with a dot ({@code dolphin.dsl.DolphinScript.Then}),
     * arrays with brackets (Groovy passes varargs to a last array parameter).
     */
    static String typeName(Class<?> type) {
        return type.getCanonicalName();
    }

    /** A single-quoted Groovy string. */
    static String literal(String text) {
        return "'" + text.replace("\\", "\\\\").replace("'", "\\'") + "'";
    }

    private static String html(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
