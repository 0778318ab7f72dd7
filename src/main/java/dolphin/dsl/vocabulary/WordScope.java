package dolphin.dsl.vocabulary;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.SortedMap;
import java.util.TreeMap;

/**
 * Where a set of words can be written: at the script's top level, inside a block ({@code mission
 * { }}, {@code pick { }}), after a word ({@code then} after {@code waitFor { }}), or after a number
 * (the units).
 */
public final class WordScope {

    /** What kind of place the scope is. */
    public enum ScopeKind {
        /** The script's top level, and every block that has no words of its own. */
        SCRIPT,
        /** A closure given to a word whose parameter names the class of its words ({@code @DelegatesTo}). */
        BLOCK,
        /** The second half of a two-word instruction: words of what the first half returns. */
        CHAIN,
        /** The units, read as properties of numbers. */
        UNITS
    }

    private final ScopeKind kind;
    private final Class<?> type;
    private final List<String> openers;
    private final SortedMap<String, WordEntry> words;

    WordScope(ScopeKind kind, Class<?> type, List<String> openers, Map<String, WordEntry> words) {
        this.kind = kind;
        this.type = type;
        this.openers = List.copyOf(openers);
        this.words = Collections.unmodifiableSortedMap(new TreeMap<>(words));
    }

    public ScopeKind kind() {
        return kind;
    }

    /** The class whose methods the words are (a block's delegate). */
    public Class<?> type() {
        return type;
    }

    /** The words that open the block, or after which the chain's words come; empty for the script and units. */
    public List<String> openers() {
        return openers;
    }

    /** The words, by name. */
    public SortedMap<String, WordEntry> words() {
        return words;
    }

    /** Where the words belong, for a message: "inside mission { }", "after waitFor { }". */
    public String where() {
        return switch (kind) {
            case SCRIPT -> "at the script's top level";
            case UNITS -> "after a number, as in 10.minutes";
            case BLOCK -> "inside " + joined(openers.stream().map(o -> o + " { }").toList());
            case CHAIN -> "after " + joined(openers);
        };
    }

    private static String joined(List<String> names) {
        if (names.size() == 1) {
            return names.get(0);
        }
        return String.join(", ", names.subList(0, names.size() - 1)) + " or " + names.get(names.size() - 1);
    }

    @Override
    public String toString() {
        return kind + " " + type.getSimpleName() + " " + openers;
    }
}
