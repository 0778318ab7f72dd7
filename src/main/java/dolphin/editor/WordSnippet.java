package dolphin.editor;

import dolphin.dsl.vocabulary.WordEntry;
import java.util.List;

/**
 * What completion inserts for a word that takes arguments, in an editor that takes snippets: the
 * word's first usage with a placeholder for each parameter it needs, the optional ones left out, so
 * that what is inserted compiles once the placeholders are filled in: {@code goPos(${1:lat}, ${2:lon})},
 * {@code pick { ${1:clauses} }}, {@code move(${1:position}, { ${2:offset} })}. The second word of a
 * two-word instruction is written in Groovy's command syntax, as scripts write it: {@code then ${1:task}}.
 */
final class WordSnippet {

    private WordSnippet() {
    }

    /** The snippet, or null for a word that needs no argument (or a unit). */
    static String of(WordEntry word, boolean secondWord) {
        if (word.unit() || word.usages().isEmpty()) {
            return null;
        }
        String usage = withoutOptional(word.usages().get(0));
        List<int[]> params = UsageParameters.of(usage, word.name());
        if (params.isEmpty()) {
            return null;
        }
        StringBuilder out = new StringBuilder(word.name());
        int copied = word.name().length();
        for (int i = 0; i < params.size(); i++) {
            int[] p = params.get(i);
            String text = usage.substring(p[0], p[1]);
            String name = text.replaceAll("[{}. ]", "");
            String placeholder = "${" + (i + 1) + ":" + name + "}";
            out.append(usage, copied, p[0]).append(text.startsWith("{") ? "{ " + placeholder + " }" : placeholder);
            copied = p[1];
        }
        out.append(usage.substring(copied));
        String snippet = out.toString();
        boolean call = snippet.startsWith(word.name() + "(") && snippet.endsWith(")");
        if (secondWord && call && !usage.startsWith(word.name() + "({")) {
            return word.name() + " " + snippet.substring(word.name().length() + 1, snippet.length() - 1);
        }
        return snippet;
    }

    /** The usage with its optional parts ({@code [, hae]}) taken out. */
    private static String withoutOptional(String usage) {
        StringBuilder kept = new StringBuilder();
        int depth = 0;
        for (char c : usage.toCharArray()) {
            if (c == '[') {
                depth++;
            } else if (c == ']') {
                depth--;
            } else if (depth == 0) {
                kept.append(c);
            }
        }
        return kept.toString();
    }
}
