package dolphin.editor;

import java.util.Map;

/**
 * One version of a script open in the editor. What requests need from it (its lines, its names) is
 * worked out once per version, on first use.
 */
final class OpenDocument {

    private final String uri;
    private final int version;
    private final String text;
    private LineMap lines;
    private Map<String, NamedPlace> typedNames;
    private Map<String, NamedPlace> definitions;

    OpenDocument(String uri, int version, String text) {
        this.uri = uri;
        this.version = version;
        this.text = text;
    }

    String uri() {
        return uri;
    }

    int version() {
        return version;
    }

    String text() {
        return text;
    }

    synchronized LineMap lines() {
        if (lines == null) {
            lines = new LineMap(text);
        }
        return lines;
    }

    /** The names the script assigns, read from its tokens: there while the script does not compile. */
    synchronized Map<String, NamedPlace> typedNames() {
        if (typedNames == null) {
            typedNames = ScriptNames.of(text);
        }
        return typedNames;
    }

    /** Where each name gets its first value: from the syntax tree, or from the tokens while the script does not parse. */
    synchronized Map<String, NamedPlace> definitions() {
        if (definitions == null) {
            definitions = parsedOrTyped();
        }
        return definitions;
    }

    private Map<String, NamedPlace> parsedOrTyped() {
        try {
            return AstNames.of(text);
        } catch (RuntimeException | StackOverflowError e) {
            // a script that does not parse (or nests too deep for the parser): its tokens still name things
            return typedNames();
        }
    }
}
