package dolphin.dsl.vocabulary;

import java.util.Collection;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.stream.Collectors;

/** "Did you mean": the known names a mistyped or half-remembered one most likely stands for. */
public final class Suggestions {

    private Suggestions() {
    }

    /**
     * At most three known names, nearest first: those within two edits of {@code name}, case aside
     * (one edit for names of up to three letters, so that {@code v2} does not suggest {@code id}),
     * then, for names of four letters or more, those that begin with it or end with it
     * ({@code land}: {@code landingPoint}, {@code returnHomeAndLand}).
     */
    public static List<String> near(String name, Collection<String> known) {
        String n = name.toLowerCase(Locale.ROOT);
        int edits = n.length() <= 3 ? 1 : 2;
        Set<String> found = new LinkedHashSet<>(known.stream()
                .filter(k -> !k.equals(name))
                .filter(k -> distance(k.toLowerCase(Locale.ROOT), n) <= edits)
                .sorted(Comparator.comparingInt((String k) -> distance(k, name)).thenComparing(k -> k))
                .toList());
        if (n.length() >= 4) {
            known.stream()
                    .filter(k -> !k.equals(name))
                    .filter(k -> {
                        String l = k.toLowerCase(Locale.ROOT);
                        return l.startsWith(n) || l.endsWith(n);
                    })
                    .sorted(Comparator.comparingInt(String::length).thenComparing(k -> k))
                    .forEach(found::add);
        }
        return found.stream().limit(3).toList();
    }

    /** "; did you mean 'a' or 'b'?", or "" when nothing is near. */
    public static String didYouMean(String name, Collection<String> known) {
        return didYouMean(near(name, known));
    }

    /** "; did you mean 'a' or 'b'?" for these names, or "" when there are none. */
    public static String didYouMean(List<String> close) {
        return close.isEmpty() ? "" : "; did you mean " + close.stream().map(k -> "'" + k + "'")
                .collect(Collectors.joining(" or ")) + "?";
    }

    /** Levenshtein distance: the fewest insertions, deletions and substitutions from a to b. */
    public static int distance(String a, String b) {
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
