package dolphin.dsl.vocabulary;

import java.util.List;

/**
 * A word of the language as the vocabulary lists it: its name, its one-line description, its forms.
 *
 * @param name what scripts write
 * @param description the {@link Word} line
 * @param signatures one per public method of that name; none for a unit ({@code 10.minutes})
 * @param unit whether it is a unit, read as a property of a number
 */
public record WordEntry(String name, String description, List<Signature> signatures, boolean unit) {

    public WordEntry {
        signatures = List.copyOf(signatures);
    }

    /** The forms, e.g. {@code (lat, lon[, hae])} and {@code (position)}; none for a unit. */
    public List<String> forms() {
        return unit ? List.of() : Forms.of(signatures);
    }

    /** The forms joined for a message: {@code (lat, lon[, hae]) or (position)}. */
    public String formsText() {
        return String.join(" or ", forms());
    }

    /** How it is written, each form in turn: {@code goPos(lat, lon[, hae])}, {@code pick { clauses }}, {@code 10.minutes}. */
    public List<String> usages() {
        if (unit) {
            return List.of("n." + name);
        }
        return forms().stream().map(this::usage).toList();
    }

    private String usage(String form) {
        // a closure alone reads as a block: pick { clauses }, not pick({ clauses })
        if (form.startsWith("({ ") && form.endsWith(" })") && form.indexOf('{', 2) < 0) {
            return name + " " + form.substring(1, form.length() - 1);
        }
        return name + form;
    }

    /** Whether some form takes this many arguments. */
    public boolean takes(int arguments) {
        return signatures.stream().anyMatch(s -> s.takes(arguments));
    }
}
