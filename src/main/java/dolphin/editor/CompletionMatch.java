package dolphin.editor;

import java.util.Locale;

/**
 * How a name offered by completion matches the word being typed, best first. Editors filter and
 * rank the list again with their own fuzzy matching; the server's order is for those that keep it.
 */
enum CompletionMatch {
    /** The name begins with what is typed, case aside: {@code mo} gives {@code move}. */
    PREFIX,
    /**
     * The name holds the typed letters in order, case aside, the first of them at its start or at one
     * of its humps: {@code mv} gives {@code move} and {@code moveFromHome}, {@code rhl} and {@code hl}
     * give {@code returnHomeAndLand}.
     */
    SUBSEQUENCE,
    /** A spelling guess for the whole word, as the checker's "did you mean" makes it: {@code mvoe} gives {@code move}. */
    GUESS;

    /** PREFIX or SUBSEQUENCE, or null when the name does not hold the typed letters so. */
    static CompletionMatch of(String typed, String name) {
        String t = typed.toLowerCase(Locale.ROOT);
        String n = name.toLowerCase(Locale.ROOT);
        if (n.startsWith(t)) {
            return PREFIX;
        }
        // the earliest start that fits leaves the most letters to find the rest in
        for (int start = 0; start < n.length(); start++) {
            if (n.charAt(start) == t.charAt(0) && beginsPart(name, start)) {
                return inOrder(t, n, start) ? SUBSEQUENCE : null;
            }
        }
        return null;
    }

    /** The name's start, a capital after a small letter or digit ({@code returnHome}), or a letter after '_'. */
    private static boolean beginsPart(String name, int at) {
        if (at == 0) {
            return true;
        }
        char before = name.charAt(at - 1);
        return before == '_' || Character.isUpperCase(name.charAt(at)) && !Character.isUpperCase(before);
    }

    private static boolean inOrder(String typed, String name, int from) {
        int t = 0;
        for (int i = from; i < name.length() && t < typed.length(); i++) {
            if (name.charAt(i) == typed.charAt(t)) {
                t++;
            }
        }
        return t == typed.length();
    }
}
