package dolphin.dsl;

import groovy.lang.Closure;
import groovy.lang.DelegatesTo;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/** What the language's blocks and words share: running a block with its builder, and "did you mean". */
public final class Blocks {

    private Blocks() {
    }

    /**
     * Runs a copy of {@code block} with {@code delegate} resolving its names first (DELEGATE_FIRST), so
     * that the block's words reach the builder and everything else the script; the caller's closure is
     * left as it was. Returns what the block returns.
     */
    public static Object run(@DelegatesTo(strategy = Closure.DELEGATE_FIRST) Closure<?> block, Object delegate, Object... arguments) {
        Closure<?> c = (Closure<?>) block.clone();
        c.setDelegate(delegate);
        c.setResolveStrategy(Closure.DELEGATE_FIRST);
        return c.call(arguments);
    }

    /** The known names within two edits of {@code name}, case aside, nearest first, at most three. */
    public static List<String> near(String name, Collection<String> known) {
        String n = name.toLowerCase(Locale.ROOT);
        return known.stream()
                .filter(k -> !k.equals(name))
                .filter(k -> distance(k.toLowerCase(Locale.ROOT), n) <= 2)
                .sorted(Comparator.comparingInt((String k) -> distance(k, name)).thenComparing(k -> k))
                .limit(3)
                .toList();
    }

    /** Levenshtein distance: the fewest insertions, deletions and substitutions from a to b. */
    static int distance(String a, String b) {
        int[] prev = new int[b.length() + 1];
        int[] cur = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            prev[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            cur[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                cur[j] = Math.min(Math.min(cur[j - 1] + 1, prev[j] + 1), prev[j - 1] + cost);
            }
            int[] swap = prev;
            prev = cur;
            cur = swap;
        }
        return prev[b.length()];
    }
}
