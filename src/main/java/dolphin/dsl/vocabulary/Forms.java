package dolphin.dsl.vocabulary;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Shows a word's forms as people write them: the methods Groovy makes for default arguments
 * ({@code goPos(lat, lon)} and {@code goPos(lat, lon, hae)}) read as one form with optional parameters,
 * {@code (lat, lon[, hae])}.
 */
final class Forms {

    private Forms() {
    }

    static List<String> of(List<Signature> signatures) {
        List<Signature> longestFirst = new ArrayList<>(signatures);
        // the class file's method order is not fixed: same length, in the order of their parameters' names and types
        longestFirst.sort(Comparator.comparingInt((Signature s) -> -s.params().size())
                .thenComparing(s -> s.params().stream().map(p -> p.name() + ":" + p.type().getName()).toList().toString()));
        List<List<Signature>> groups = new ArrayList<>();
        for (Signature s : longestFirst) {
            List<Signature> group = groups.stream().filter(g -> joins(g.get(0), s)).findFirst().orElse(null);
            if (group == null) {
                groups.add(new ArrayList<>(List.of(s)));
            } else {
                group.add(s);
            }
        }
        return groups.stream().map(Forms::render).toList();
    }

    /** A shorter form is the longest with parameters left out, the first one kept (or none at all). */
    private static boolean joins(Signature longest, Signature s) {
        if (s.varargs() != longest.varargs() || !longest.contains(s)) {
            return false;
        }
        return s.params().isEmpty() || Signature.same(s.params().get(0), longest.params().get(0));
    }

    private static String render(List<Signature> group) {
        Signature longest = group.get(0);
        List<Param> params = longest.params();
        boolean nested = group.stream().allMatch(s -> isPrefix(s, longest));
        StringBuilder out = new StringBuilder("(");
        int open = 0;
        for (int i = 0; i < params.size(); i++) {
            Param p = params.get(i);
            final int index = i;
            boolean required = group.stream().allMatch(s -> s.params().stream().anyMatch(q -> Signature.same(q, params.get(index))));
            String shown = p.shown() + (longest.varargs() && i == params.size() - 1 ? "..." : "");
            String comma = i == 0 ? "" : ", ";
            if (required) {
                out.append(comma).append(shown);
            } else if (nested) {
                out.append('[').append(comma).append(shown);
                open++;
            } else {
                out.append('[').append(comma).append(shown).append(']');
            }
        }
        out.append("]".repeat(open)).append(')');
        return out.toString();
    }

    private static boolean isPrefix(Signature s, Signature longest) {
        for (int i = 0; i < s.params().size(); i++) {
            if (!Signature.same(s.params().get(i), longest.params().get(i))) {
                return false;
            }
        }
        return true;
    }
}
