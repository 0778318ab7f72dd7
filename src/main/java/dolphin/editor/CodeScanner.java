package dolphin.editor;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.List;
import java.util.function.BiConsumer;

/**
 * Reads a script's text up to the cursor the way Groovy would tokenise it, without parsing it, so it
 * works on code that does not compile yet: it skips comments and strings (but not the code of a
 * {@code ${ }} inside one), keeps a stack of the open brackets with the word before each, and the
 * tokens of the statement the cursor is in. One pass, no recursion: any text, of any size, is read.
 */
final class CodeScanner {

    private enum Mode { CODE, STRING, LINE_COMMENT, BLOCK_COMMENT }

    private static final String OPERATORS = "=<>!&|+-*/%^~?:";

    private final String text;
    private final int end;
    private final Deque<ScanFrame> frames = new ArrayDeque<>();
    private final BiConsumer<ScanFrame, ScanToken> listener;
    private Mode mode = Mode.CODE;
    private String quote;
    private int at;

    private CodeScanner(String text, int end, BiConsumer<ScanFrame, ScanToken> listener) {
        this.text = text;
        this.end = end;
        this.listener = listener;
        frames.push(new ScanFrame(ScanFrame.FrameKind.SCRIPT, null, 0, null));
    }

    /** What the code before {@code offset} says about that place. */
    static CursorContext scan(String text, int offset) {
        int end = Math.max(0, Math.min(offset, text.length()));
        CodeScanner scanner = new CodeScanner(text, end, (frame, token) -> { });
        scanner.read();
        List<ScanFrame> outerFirst = new ArrayList<>(scanner.frames);
        Collections.reverse(outerFirst);
        return new CursorContext(end, scanner.mode == Mode.CODE, outerFirst);
    }

    /** Reads the whole text, telling {@code each} every token as it joins its statement (the frame holds the statement). */
    static void eachToken(String text, BiConsumer<ScanFrame, ScanToken> each) {
        new CodeScanner(text, text.length(), each).read();
    }

    private void read() {
        while (at < end) {
            switch (mode) {
                case CODE -> code();
                case STRING -> string();
                case LINE_COMMENT -> lineComment();
                case BLOCK_COMMENT -> blockComment();
            }
        }
    }

    private void add(ScanToken token) {
        top().add(token);
        listener.accept(top(), token);
    }

    private ScanFrame top() {
        return frames.peek();
    }

    private void code() {
        char c = text.charAt(at);
        if (c == '\n') {
            if (!top().continuesAtLineEnd()) {
                top().endStatement();
            }
            at++;
        } else if (Character.isWhitespace(c)) {
            at++;
        } else if (startsWith("//")) {
            mode = Mode.LINE_COMMENT;
            at += 2;
        } else if (startsWith("/*")) {
            mode = Mode.BLOCK_COMMENT;
            at += 2;
        } else if (c == '\'' || c == '"') {
            quote = startsWith("'''") || startsWith("\"\"\"") ? String.valueOf(c).repeat(3) : String.valueOf(c);
            add(new ScanToken(ScanToken.TokenKind.STRING, quote, at, at + quote.length()));
            mode = Mode.STRING;
            at += quote.length();
        } else if (Character.isJavaIdentifierStart(c)) {
            int start = at;
            while (at < end && Character.isJavaIdentifierPart(text.charAt(at))) {
                at++;
            }
            add(new ScanToken(ScanToken.TokenKind.WORD, text.substring(start, at), start, at));
        } else if (Character.isDigit(c)) {
            int start = at;
            number();
            add(new ScanToken(ScanToken.TokenKind.NUMBER, text.substring(start, at), start, at));
        } else if (c == '{') {
            frames.push(new ScanFrame(ScanFrame.FrameKind.BRACE, braceOpener(), at, null));
            at++;
        } else if (c == '(' || c == '[') {
            ScanToken last = top().last();
            String word = last != null && last.kind() == ScanToken.TokenKind.WORD ? last.text() : null;
            frames.push(new ScanFrame(c == '(' ? ScanFrame.FrameKind.PAREN : ScanFrame.FrameKind.BRACKET, word, at, null));
            at++;
        } else if (c == '}' || c == ')' || c == ']') {
            close(c);
            at++;
        } else if (c == ';') {
            top().endStatement();
            at++;
        } else if (c == ',' || c == '.' || OPERATORS.indexOf(c) < 0) {
            add(new ScanToken(ScanToken.TokenKind.SYMBOL, String.valueOf(c), at, at + 1));
            at++;
        } else {
            int start = at;
            while (at < end && OPERATORS.indexOf(text.charAt(at)) >= 0 && !startsWith("//") && !startsWith("/*")) {
                at++;
            }
            add(new ScanToken(ScanToken.TokenKind.SYMBOL, text.substring(start, at), start, at));
        }
    }

    /**
     * The word a '{' belongs to: the word just before it ({@code mission { }}), the call before its
     * parentheses ({@code def f(a) { }}), or, as an argument in parentheses, the call's word
     * ({@code move(p, { north 10 })}).
     */
    private String braceOpener() {
        ScanFrame top = top();
        ScanToken last = top.last();
        if (last == null || last.is(ScanToken.TokenKind.SYMBOL, ",")) {
            return top.kind == ScanFrame.FrameKind.PAREN ? top.opener : null;
        }
        if (last.kind() == ScanToken.TokenKind.WORD) {
            return last.text();
        }
        return last.kind() == ScanToken.TokenKind.GROUP && !last.text().isEmpty() ? last.text() : null;
    }

    /** Closes the nearest open bracket of the same kind; a closer with none open is ignored. */
    private void close(char c) {
        for (ScanFrame f : frames) {
            if (f.kind == ScanFrame.FrameKind.SCRIPT || f.kind == ScanFrame.FrameKind.INTERPOLATION && c != '}') {
                return;
            }
            if (matches(f.kind, c)) {
                ScanFrame popped;
                do {
                    popped = frames.pop(); // brackets left open inside f end with it
                } while (popped != f);
                if (f.kind == ScanFrame.FrameKind.INTERPOLATION) {
                    mode = Mode.STRING;
                    quote = f.quote;
                } else {
                    ScanToken.TokenKind kind = f.kind == ScanFrame.FrameKind.BRACE ? ScanToken.TokenKind.BLOCK : ScanToken.TokenKind.GROUP;
                    add(new ScanToken(kind, f.opener == null ? "" : f.opener, f.start, at + 1));
                }
                return;
            }
        }
    }

    private static boolean matches(ScanFrame.FrameKind kind, char closer) {
        return switch (kind) {
            case BRACE, INTERPOLATION -> closer == '}';
            case PAREN -> closer == ')';
            case BRACKET -> closer == ']';
            case SCRIPT -> false;
        };
    }

    /** Digits, a fraction, an exponent, a type suffix ({@code 10}, {@code 0.5}, {@code 1e3}, {@code 2L}); not the '.' of {@code 10.minutes}. */
    private void number() {
        if (startsWith("0x") || startsWith("0X")) {
            at += 2;
            while (at < end && Character.isLetterOrDigit(text.charAt(at))) {
                at++;
            }
            return;
        }
        while (at < end) {
            char c = text.charAt(at);
            if (Character.isDigit(c) || c == '_') {
                at++;
            } else if (c == '.' && at + 1 < end && Character.isDigit(text.charAt(at + 1))) {
                at++;
            } else if ((c == 'e' || c == 'E') && exponentFollows()) {
                at += Character.isDigit(text.charAt(at + 1)) ? 1 : 2;
            } else {
                if ("lLgGdDfFiI".indexOf(c) >= 0) {
                    at++;
                }
                return;
            }
        }
    }

    private boolean exponentFollows() {
        int next = at + 1;
        if (next < end && (text.charAt(next) == '+' || text.charAt(next) == '-')) {
            next++;
        }
        return next < end && Character.isDigit(text.charAt(next));
    }

    private void string() {
        char c = text.charAt(at);
        if (c == '\\') {
            at += 2;
        } else if (quote.charAt(0) == '"' && startsWith("${")) {
            frames.push(new ScanFrame(ScanFrame.FrameKind.INTERPOLATION, null, at, quote));
            mode = Mode.CODE;
            at += 2;
        } else if (startsWith(quote)) {
            mode = Mode.CODE;
            at += quote.length();
        } else if (c == '\n' && quote.length() == 1) {
            // an unclosed one-line string ends with its line, so one missing quote does not hide the rest of the script
            mode = Mode.CODE;
        } else {
            at++;
        }
        at = Math.min(at, end);
    }

    private void lineComment() {
        int next = text.indexOf('\n', at);
        if (next < 0 || next >= end) {
            at = end;
        } else {
            mode = Mode.CODE;
            at = next;
        }
    }

    private void blockComment() {
        int close = text.indexOf("*/", at);
        if (close < 0 || close + 2 > end) {
            at = end;
        } else {
            mode = Mode.CODE;
            at = close + 2;
        }
    }

    private boolean startsWith(String s) {
        return text.startsWith(s, at) && at + s.length() <= end;
    }
}
