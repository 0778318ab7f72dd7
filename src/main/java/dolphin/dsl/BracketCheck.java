package dolphin.dsl;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Optional;

/**
 * Finds the first unbalanced bracket of a script, skipping strings and comments. Groovy's parser
 * reports a missing '}' as "Unexpected input" somewhere else; this says which bracket is open.
 * Used only to explain a failed compilation, so a rare misreading (slashy strings) costs nothing.
 */
final class BracketCheck {

    private record Open(char ch, int line, int column) {
    }

    private BracketCheck() {
    }

    static Optional<ScriptError> check(String source, String file) {
        Deque<Open> stack = new ArrayDeque<>();
        int line = 1;
        int col = 0;
        int i = 0;
        int n = source.length();
        while (i < n) {
            char c = source.charAt(i);
            col++;
            if (c == '\n') {
                line++;
                col = 0;
                i++;
                continue;
            }
            if (c == '/' && i + 1 < n && source.charAt(i + 1) == '/') {
                while (i < n && source.charAt(i) != '\n') {
                    i++;
                }
                continue;
            }
            if (c == '/' && i + 1 < n && source.charAt(i + 1) == '*') {
                int end = source.indexOf("*/", i + 2);
                int stop = end < 0 ? n : end + 2;
                for (int k = i; k < stop; k++) {
                    if (source.charAt(k) == '\n') {
                        line++;
                        col = 0;
                    }
                }
                i = stop;
                continue;
            }
            if (c == '\'' || c == '"') {
                String quote = source.startsWith(String.valueOf(c).repeat(3), i) ? String.valueOf(c).repeat(3) : String.valueOf(c);
                int k = i + quote.length();
                while (k < n && !source.startsWith(quote, k)) {
                    if (source.charAt(k) == '\\') {
                        k++;
                    } else if (source.charAt(k) == '\n') {
                        if (quote.length() == 1) {
                            break;
                        }
                        line++;
                        col = 0;
                    }
                    k++;
                }
                i = Math.min(n, k + quote.length());
                continue;
            }
            if (c == '{' || c == '(' || c == '[') {
                stack.push(new Open(c, line, col));
            } else if (c == '}' || c == ')' || c == ']') {
                char expected = stack.isEmpty() ? 0 : closing(stack.peek().ch);
                if (c != expected) {
                    String want = stack.isEmpty() ? "nothing is open here" : "expected '" + expected
                            + "' to close the '" + stack.peek().ch + "' of line " + stack.peek().line;
                    return Optional.of(new ScriptError(file, line, col, "unbalanced '" + c + "': " + want));
                }
                stack.pop();
            }
            i++;
        }
        if (stack.isEmpty()) {
            return Optional.empty();
        }
        // The innermost unclosed bracket is where the writer most likely forgot the closing one.
        Open open = stack.peek();
        return Optional.of(new ScriptError(file, open.line, open.column,
                "the '" + open.ch + "' opened here is never closed: expected a '" + closing(open.ch) + "' before the end of the script"));
    }

    private static char closing(char open) {
        return switch (open) {
            case '{' -> '}';
            case '(' -> ')';
            default -> ']';
        };
    }
}
