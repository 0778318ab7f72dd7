package dolphin.editor;

import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionItemKind;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.jsonrpc.messages.Either;

/**
 * The words valid at the cursor, found from the text before it ({@link CodeScanner}), so code that
 * does not compile yet gets them: after a number and a dot the units; where a statement waits for its
 * second word ({@code waitFor { c } }) that word; elsewhere the words of the blocks around the cursor,
 * innermost first, then the script's words, then the script's own variables. Only those that begin
 * with what is typed; nothing inside a string or a comment, nor after another dot ({@code v.id}).
 */
final class Completions {

    private final VisibleWords words;

    Completions(VisibleWords words) {
        this.words = words;
    }

    List<CompletionItem> at(OpenDocument document, int offset) {
        CursorContext context = CodeScanner.scan(document.text(), offset);
        if (!context.inCode()) {
            return List.of();
        }
        Listing listing = new Listing(context.prefix());
        if (context.afterNumberDot()) {
            listing.words(words.vocabulary().units(), CompletionItemKind.Unit);
            return listing.items;
        }
        if (context.afterDot()) {
            return List.of();
        }
        Optional<WordScope> chain = words.pendingChain(context.beforePrefix());
        if (chain.isPresent()) {
            listing.words(chain.get(), CompletionItemKind.Keyword);
            return listing.items;
        }
        for (WordScope scope : words.at(context)) {
            listing.words(scope, CompletionItemKind.Function);
        }
        listing.names(document.typedNames().values().stream()
                .filter(n -> n.offset() != context.prefixStart()).toList(), document.lines());
        return listing.items;
    }

    /** The items in order, each group after the one before (sortText), each name once, the typed prefix matched. */
    private static final class Listing {
        private final String prefix;
        private final List<CompletionItem> items = new ArrayList<>();
        private final Set<String> names = new HashSet<>();
        private int group;

        Listing(String prefix) {
            this.prefix = prefix.toLowerCase(Locale.ROOT);
        }

        void words(WordScope scope, CompletionItemKind kind) {
            group++;
            for (WordEntry w : scope.words().values()) {
                CompletionItem item = item(w.name(), kind);
                if (item != null) {
                    item.setDetail(WordText.usages(w));
                    item.setDocumentation(Either.forRight(new MarkupContent(MarkupKind.MARKDOWN, w.description())));
                }
            }
        }

        void names(List<NamedPlace> places, LineMap lines) {
            group++;
            for (NamedPlace place : places) {
                CompletionItem item = item(place.name(), place.method() ? CompletionItemKind.Method : CompletionItemKind.Variable);
                if (item != null) {
                    item.setDetail((place.method() ? "defined" : "assigned") + " at line " + (lines.position(place.offset()).getLine() + 1));
                }
            }
        }

        private CompletionItem item(String name, CompletionItemKind kind) {
            if (!name.toLowerCase(Locale.ROOT).startsWith(prefix) || !names.add(name)) {
                return null;
            }
            CompletionItem item = new CompletionItem(name);
            item.setKind(kind);
            item.setSortText(String.format("%02d%s", group, name));
            items.add(item);
            return item;
        }
    }
}
