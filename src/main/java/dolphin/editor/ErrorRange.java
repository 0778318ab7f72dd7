package dolphin.editor;

import dolphin.dsl.ScriptError;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;

/**
 * Where the editor underlines a script error: the word at its line and column (1-based), the
 * character there if it is no word, the rest of the line if the column is past its text; the whole
 * line when the error has no column, the first line when it has no line. A line past the end of the
 * script (Groovy reports an unfinished last statement there) is the last line.
 */
final class ErrorRange {

    private ErrorRange() {
    }

    static Range of(ScriptError error, String text, LineMap lines) {
        int line = Math.min(Math.max(error.line(), 1), lines.lineCount()) - 1;
        int start = lines.lineStart(line);
        int end = lines.lineEnd(line);
        if (error.column() <= 0 || error.line() > lines.lineCount()) {
            return new Range(lines.position(start), lines.position(end));
        }
        int at = Math.min(start + error.column() - 1, end);
        WordSpan word = at < end ? WordSpan.at(text, at) : null;
        if (word != null && word.start() <= at && at < word.end()) {
            return new Range(lines.position(word.start()), lines.position(word.end()));
        }
        if (at < end && !Character.isWhitespace(text.charAt(at))) {
            return new Range(lines.position(at), lines.position(at + 1));
        }
        return new Range(lines.position(at), new Position(line, end - start));
    }
}
