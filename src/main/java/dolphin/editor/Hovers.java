package dolphin.editor;

import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;
import java.util.Optional;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.Range;

/**
 * What the word under the cursor is: a word of the language as the blocks around it see it (its
 * usages, what it does, the units of its numbers, where it may be written), a unit after a number,
 * or one of the script's variables (where it gets its first value).
 */
final class Hovers {

    private final VisibleWords words;

    Hovers(VisibleWords words) {
        this.words = words;
    }

    Hover at(OpenDocument document, int offset) {
        String text = document.text();
        WordSpan span = WordSpan.at(text, offset);
        if (span == null) {
            return null;
        }
        CursorContext context = CodeScanner.scan(text, span.start());
        if (!context.inCode()) {
            return null;
        }
        String name = span.of(text);
        String markdown;
        if (context.afterNumberDot()) {
            WordEntry unit = words.vocabulary().units().words().get(name);
            markdown = unit == null ? null : word(new ScopedWord(unit, words.vocabulary().units()), true);
        } else if (context.afterDot()) {
            markdown = null;
        } else {
            markdown = words.find(name, words.at(context)).map(w -> word(w, true))
                    .or(() -> Optional.ofNullable(document.definitions().get(name)).map(p -> variable(document, p)))
                    .or(() -> words.anywhere(name).map(w -> word(w, false)))
                    .orElse(null);
        }
        if (markdown == null) {
            return null;
        }
        LineMap lines = document.lines();
        return new Hover(new MarkupContent(MarkupKind.MARKDOWN, markdown),
                new Range(lines.position(span.start()), lines.position(span.end())));
    }

    private static String word(ScopedWord w, boolean belongsHere) {
        WordEntry e = w.entry();
        StringBuilder md = new StringBuilder("```groovy\n").append(String.join("\n", e.usages())).append("\n```\n\n")
                .append(e.description());
        String units = WordText.units(e);
        if (!units.isEmpty()) {
            md.append("\n\nUnits: ").append(units);
        }
        if (w.scope().kind() != WordScope.ScopeKind.SCRIPT) {
            md.append(belongsHere ? "\n\nWritten " : "\n\nBelongs ").append(w.scope().where());
        }
        return md.toString();
    }

    private static String variable(OpenDocument document, NamedPlace place) {
        LineMap lines = document.lines();
        int line = lines.position(place.offset()).getLine();
        return "```groovy\n" + lines.lineText(line).strip() + "\n```\n\n"
                + (place.method() ? "Method defined" : "Variable assigned") + " at line " + (line + 1);
    }
}
