package dolphin.editor;

import dolphin.dsl.vocabulary.Suggestions;
import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionItemKind;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.InsertTextFormat;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;

/**
 * The words valid at the cursor, found from the text before it ({@link CodeScanner}), so code that
 * does not compile yet gets them: after a number and a dot the units; where a statement waits for its
 * second word ({@code waitFor { c } }) that word; elsewhere the words of the blocks around the cursor,
 * innermost first, then the script's words, then the script's own variables. Nothing inside a string
 * or a comment, nor after another dot ({@code v.id}).
 *
 * <p>Of those, the ones that match the word being typed ({@link CompletionMatch}): those that begin
 * with it, then those that hold its letters in order ({@code mv}: {@code move}), then spelling guesses
 * for the whole word ({@code mvoe}: {@code move}); within each, in the order above. Editors filter and
 * rank again as the user types, fuzzily: each item replaces the whole word under the cursor and says
 * what to match ({@code filterText}); a list cut at {@link #MOST_ITEMS}, or holding guesses (which
 * depend on the whole word), is marked incomplete so the editor asks again.
 */
final class Completions {

    /** The most items one answer holds: a script's thousands of variables are not all sent at each key. */
    static final int MOST_ITEMS = 200;

    private final VisibleWords words;

    Completions(VisibleWords words) {
        this.words = words;
    }

    /** The items; with {@code snippets} (the editor takes them), words with arguments insert placeholders for them. */
    CompletionList at(OpenDocument document, int offset, boolean snippets) {
        CursorContext context = CodeScanner.scan(document.text(), offset);
        if (!context.inCode() || context.afterDot() && !context.afterNumberDot()) {
            return new CompletionList(false, List.of());
        }
        Offers offers = new Offers();
        Optional<WordScope> chain = context.afterNumberDot() ? Optional.empty() : words.pendingChain(context.beforePrefix());
        if (context.afterNumberDot()) {
            offers.words(words.vocabulary().units(), CompletionItemKind.Unit, false);
        } else if (chain.isPresent()) {
            offers.words(chain.get(), CompletionItemKind.Keyword, true);
        } else {
            for (WordScope scope : words.at(context)) {
                offers.words(scope, CompletionItemKind.Function, false);
            }
            offers.names(document.typedNames().values().stream()
                    .filter(n -> n.offset() != context.prefixStart()).toList(), document.lines());
        }
        return offers.ranked(TypedWord.at(document.text(), context), snippets, document.lines());
    }

    /**
     * A name that can be written here.
     *
     * @param group its place in the order of scopes: the innermost block's words first
     * @param word the word of the language, null for one of the script's names
     * @param secondWord whether it is the second word of a two-word instruction ({@code then})
     */
    private record Offer(String name, CompletionItemKind kind, int group, String detail, WordEntry word, boolean secondWord) {
    }

    /** An offer and how it matches; the order of the sortText: the match, then the scope, then the name. */
    private record RankedOffer(Offer offer, CompletionMatch match, String sortText) {

        static RankedOffer of(Offer offer, CompletionMatch match) {
            return new RankedOffer(offer, match, String.format(Locale.ROOT, "%d%02d%s", match.ordinal(), offer.group(), offer.name()));
        }
    }

    /** The names in the order of their scopes, each name once, in the first scope that has it. */
    private static final class Offers {
        private final Map<String, Offer> byName = new LinkedHashMap<>();
        private int group;

        void words(WordScope scope, CompletionItemKind kind, boolean secondWord) {
            group++;
            for (WordEntry w : scope.words().values()) {
                byName.putIfAbsent(w.name(), new Offer(w.name(), kind, group, WordText.usages(w), w, secondWord));
            }
        }

        void names(List<NamedPlace> places, LineMap lines) {
            group++;
            for (NamedPlace place : places) {
                String detail = (place.method() ? "defined" : "assigned") + " at line " + (lines.position(place.offset()).getLine() + 1);
                byName.putIfAbsent(place.name(), new Offer(place.name(),
                        place.method() ? CompletionItemKind.Method : CompletionItemKind.Variable, group, detail, null, false));
            }
        }

        CompletionList ranked(TypedWord typed, boolean snippets, LineMap lines) {
            List<RankedOffer> found = new ArrayList<>();
            List<String> unmatched = new ArrayList<>();
            for (Offer offer : byName.values()) {
                CompletionMatch match = CompletionMatch.of(typed.typed(), offer.name());
                if (match == null) {
                    unmatched.add(offer.name());
                } else {
                    found.add(RankedOffer.of(offer, match));
                }
            }
            boolean guessed = false;
            if (!typed.whole().isEmpty()) {
                for (String guess : Suggestions.near(typed.whole(), unmatched)) {
                    found.add(RankedOffer.of(byName.get(guess), CompletionMatch.GUESS));
                    guessed = true;
                }
            }
            found.sort(Comparator.comparing(RankedOffer::sortText));
            Range replaced = new Range(lines.position(typed.start()), lines.position(typed.end()));
            List<CompletionItem> items = found.stream().limit(MOST_ITEMS)
                    .map(r -> item(r, typed, replaced, snippets && !typed.argumentsFollow())).toList();
            return new CompletionList(guessed || found.size() > MOST_ITEMS, items);
        }

        private static CompletionItem item(RankedOffer ranked, TypedWord typed, Range replaced, boolean snippets) {
            Offer offer = ranked.offer();
            CompletionItem item = new CompletionItem(offer.name());
            item.setKind(offer.kind());
            item.setDetail(offer.detail());
            item.setSortText(ranked.sortText());
            // a guess does not hold the typed letters: matched as the word typed, the editor keeps it
            item.setFilterText(ranked.match() == CompletionMatch.GUESS ? typed.whole() : offer.name());
            String snippet = snippets && offer.word() != null ? WordSnippet.of(offer.word(), offer.secondWord()) : null;
            item.setTextEdit(Either.forLeft(new TextEdit(replaced, snippet == null ? offer.name() : snippet)));
            if (snippet != null) {
                item.setInsertTextFormat(InsertTextFormat.Snippet);
            }
            if (offer.word() != null) {
                item.setDocumentation(Either.forRight(new MarkupContent(MarkupKind.MARKDOWN, offer.word().description())));
            }
            return item;
        }
    }
}
