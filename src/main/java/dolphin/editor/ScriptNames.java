package dolphin.editor;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The names a script assigns or declares, found in its tokens ({@link CodeScanner}) rather than by
 * parsing, so a script that does not compile has them too: {@code name = ...} (not {@code a.b = ...}
 * nor {@code ==}), {@code def name} and {@code def name(...)}. The first place of each name counts.
 */
final class ScriptNames {

    private ScriptNames() {
    }

    static Map<String, NamedPlace> of(String text) {
        Map<String, NamedPlace> found = new LinkedHashMap<>();
        CodeScanner.eachToken(text, (frame, token) -> {
            List<ScanToken> s = frame.statement();
            int n = s.size();
            if (token.is(ScanToken.TokenKind.SYMBOL, "=") && n >= 2 && s.get(n - 2).kind() == ScanToken.TokenKind.WORD
                    && (n < 3 || !s.get(n - 3).is(ScanToken.TokenKind.SYMBOL, "."))) {
                ScanToken name = s.get(n - 2);
                found.putIfAbsent(name.text(), new NamedPlace(name.text(), name.start(), false));
            } else if (token.kind() == ScanToken.TokenKind.WORD && n >= 2 && s.get(n - 2).is(ScanToken.TokenKind.WORD, "def")) {
                found.putIfAbsent(token.text(), new NamedPlace(token.text(), token.start(), opensParenthesis(text, token.end())));
            }
        });
        return found;
    }

    private static boolean opensParenthesis(String text, int from) {
        int at = from;
        while (at < text.length() && Character.isWhitespace(text.charAt(at))) {
            at++;
        }
        return at < text.length() && text.charAt(at) == '(';
    }
}
