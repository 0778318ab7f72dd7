package dolphin.editor;

import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Range;

/** Go to definition: a script's variable or method leads to where it gets its first value. */
final class Definitions {

    Location at(OpenDocument document, int offset) {
        String text = document.text();
        WordSpan span = WordSpan.at(text, offset);
        if (span == null) {
            return null;
        }
        CursorContext context = CodeScanner.scan(text, span.start());
        NamedPlace place = context.inCode() && !context.afterDot() ? document.definitions().get(span.of(text)) : null;
        if (place == null) {
            return null;
        }
        LineMap lines = document.lines();
        return new Location(document.uri(), new Range(lines.position(place.offset()),
                lines.position(place.offset() + place.name().length())));
    }
}
