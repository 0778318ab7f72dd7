package dolphin.dsl.check;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.List;
import org.codehaus.groovy.control.SourceUnit;

/**
 * A script's text by the 1-based lines and columns of Groovy's syntax tree, for the checks' fixes,
 * which rewrite a part of it: a fix is offered only where the text is what the tree says it is. Read
 * on first use, so a script without mistakes is not read again.
 */
public final class ScriptText {

    private final SourceUnit source;
    private List<String> lines;

    private ScriptText(SourceUnit source) {
        this.source = source;
    }

    public static ScriptText lazy(SourceUnit source) {
        return new ScriptText(source);
    }

    private List<String> lines() {
        if (lines == null) {
            try (BufferedReader reader = new BufferedReader(source.getSource().getReader())) {
                lines = reader.lines().toList();
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return lines;
    }

    /** Line {@code n} (1-based), "" past the end. */
    private String line(int n) {
        return n >= 1 && n <= lines().size() ? lines().get(n - 1) : "";
    }

    /** The text from line:column up to endLine:endColumn (excluded), lines joined by '\n'; "" for an empty or inverted span. */
    public String between(int line, int column, int endLine, int endColumn) {
        if (line < 1 || endLine > lines().size() || endLine < line || endLine == line && endColumn <= column) {
            return "";
        }
        if (line == endLine) {
            String l = line(line);
            return l.substring(Math.min(Math.max(column, 1) - 1, l.length()), Math.min(endColumn - 1, l.length()));
        }
        String first = line(line);
        StringBuilder s = new StringBuilder(first.substring(Math.min(Math.max(column, 1) - 1, first.length())));
        for (int n = line + 1; n < endLine; n++) {
            s.append('\n').append(line(n));
        }
        String last = line(endLine);
        return s.append('\n').append(last, 0, Math.min(Math.max(endColumn, 1) - 1, last.length())).toString();
    }
}
