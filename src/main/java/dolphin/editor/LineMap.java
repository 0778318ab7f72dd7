package dolphin.editor;

import java.util.Arrays;
import org.eclipse.lsp4j.Position;

/**
 * Offsets in a text and LSP positions (0-based line, UTF-16 character, as Java strings count), both
 * ways. Lines end at '\n'; a '\r' before it counts as part of the line's end, not its text.
 */
final class LineMap {

    private final String text;
    private final int[] starts;

    LineMap(String text) {
        this.text = text;
        int[] found = new int[16];
        int count = 1;
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                if (count == found.length) {
                    found = Arrays.copyOf(found, count * 2);
                }
                found[count++] = i + 1;
            }
        }
        this.starts = Arrays.copyOf(found, count);
    }

    int lineCount() {
        return starts.length;
    }

    /** The offset of a position; a position past its line's end or past the text is moved back onto it. */
    int offset(Position p) {
        int line = Math.max(0, Math.min(p.getLine(), starts.length - 1));
        return Math.min(starts[line] + Math.max(0, p.getCharacter()), lineEnd(line));
    }

    Position position(int offset) {
        int at = Math.max(0, Math.min(offset, text.length()));
        int line = Arrays.binarySearch(starts, at);
        if (line < 0) {
            line = -line - 2;
        }
        return new Position(line, at - starts[line]);
    }

    int lineStart(int line) {
        return starts[line];
    }

    /** Where the line's text ends, before its '\n' (and a '\r' before that). */
    int lineEnd(int line) {
        int end = line + 1 < starts.length ? starts[line + 1] - 1 : text.length();
        return end > starts[line] && text.charAt(end - 1) == '\r' ? end - 1 : end;
    }

    String lineText(int line) {
        return text.substring(starts[line], lineEnd(line));
    }
}
