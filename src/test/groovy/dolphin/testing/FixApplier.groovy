package dolphin.testing

import dolphin.dsl.check.QuickFix

/** A script's text with a quick fix applied, as an editor applies it: by its 1-based lines and columns. */
final class FixApplier {

    private FixApplier() {
    }

    static String applied(String text, QuickFix fix) {
        List<Integer> starts = [0]
        text.eachWithIndex { String c, int i -> if (c == '\n') starts << i + 1 }
        int from = starts[fix.line() - 1] + fix.column() - 1
        int to = starts[fix.endLine() - 1] + fix.endColumn() - 1
        text.substring(0, from) + fix.replacement() + text.substring(to)
    }
}
