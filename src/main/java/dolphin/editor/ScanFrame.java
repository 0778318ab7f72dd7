package dolphin.editor;

import java.util.ArrayList;
import java.util.List;

/**
 * An open bracket while {@link CodeScanner} reads (or the script itself, at the bottom): the word
 * that opened it and the tokens of its current statement.
 */
final class ScanFrame {

    enum FrameKind {
        SCRIPT, BRACE, PAREN, BRACKET,
        /** {@code ${ }} inside a double-quoted string: code, then the string goes on */
        INTERPOLATION
    }

    final FrameKind kind;
    /** The word before a brace ({@code mission} of {@code mission { }}) or a parenthesis ({@code goPos(}); null if none. */
    final String opener;
    final int start;
    /** For an interpolation, the quotes of the string it is in. */
    final String quote;
    private final List<ScanToken> statement = new ArrayList<>();

    ScanFrame(FrameKind kind, String opener, int start, String quote) {
        this.kind = kind;
        this.opener = opener;
        this.start = start;
        this.quote = quote;
    }

    void add(ScanToken token) {
        statement.add(token);
    }

    /** Inside braces and at the top level a statement ends at ';' or at a line end that does not continue it. */
    void endStatement() {
        statement.clear();
    }

    List<ScanToken> statement() {
        return statement;
    }

    ScanToken last() {
        return statement.isEmpty() ? null : statement.get(statement.size() - 1);
    }

    /** Whether a line end goes on with the statement: inside brackets, or after a comma or an operator. */
    boolean continuesAtLineEnd() {
        if (kind == FrameKind.PAREN || kind == FrameKind.BRACKET) {
            return true;
        }
        ScanToken last = last();
        return last != null && last.kind() == ScanToken.TokenKind.SYMBOL;
    }
}
