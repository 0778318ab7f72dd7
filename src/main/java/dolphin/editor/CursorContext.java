package dolphin.editor;

import java.util.List;

/**
 * What the code before a place says about it ({@link CodeScanner}): whether it is code, the open
 * brackets around it, the statement it is in and the word being typed there.
 *
 * @param offset the place
 * @param inCode false inside a comment or a string
 * @param frames the open brackets, the script's level first
 */
record CursorContext(int offset, boolean inCode, List<ScanFrame> frames) {

    ScanFrame innermost() {
        return frames.get(frames.size() - 1);
    }

    /** The words before the '{' of each open brace, outermost first; braces without one are left out. */
    List<String> blockOpeners() {
        return frames.stream().filter(f -> f.kind == ScanFrame.FrameKind.BRACE && f.opener != null).map(f -> f.opener).toList();
    }

    /** The word that ends at the place, being typed; "" if none. */
    String prefix() {
        ScanToken p = prefixToken();
        return p == null ? "" : p.text();
    }

    int prefixStart() {
        ScanToken p = prefixToken();
        return p == null ? offset : p.start();
    }

    /** The tokens of the statement before the word being typed. */
    List<ScanToken> beforePrefix() {
        List<ScanToken> s = innermost().statement();
        return prefixToken() == null ? s : s.subList(0, s.size() - 1);
    }

    /** The word being typed comes right after a '.': a member ({@code v.id}) or a unit ({@code 10.minutes}). */
    boolean afterDot() {
        ScanToken before = lastBeforePrefix();
        return before != null && before.is(ScanToken.TokenKind.SYMBOL, ".") && before.end() == prefixStart();
    }

    /** The word being typed is a number's property: {@code 10.min}. */
    boolean afterNumberDot() {
        List<ScanToken> before = beforePrefix();
        if (!afterDot() || before.size() < 2) {
            return false;
        }
        ScanToken number = before.get(before.size() - 2);
        return number.kind() == ScanToken.TokenKind.NUMBER && number.end() == before.get(before.size() - 1).start();
    }

    private ScanToken lastBeforePrefix() {
        List<ScanToken> before = beforePrefix();
        return before.isEmpty() ? null : before.get(before.size() - 1);
    }

    private ScanToken prefixToken() {
        ScanToken last = innermost().last();
        return inCode && last != null && last.kind() == ScanToken.TokenKind.WORD && last.end() == offset ? last : null;
    }
}
