package dolphin.editor;

import dolphin.dsl.vocabulary.Param;
import dolphin.dsl.vocabulary.Vocabulary;
import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * Which words can be written at a place, from the words that opened the blocks around it: inside a
 * block its own words come first, then those of the blocks around it, then the script's (Groovy's
 * DELEGATE_FIRST). A brace whose word opens no block of words ({@code waitFor { }}, {@code if (c) { }})
 * sees what its surroundings see.
 */
final class VisibleWords {

    private final Vocabulary vocabulary;

    VisibleWords(Vocabulary vocabulary) {
        this.vocabulary = vocabulary;
    }

    Vocabulary vocabulary() {
        return vocabulary;
    }

    /** The scopes whose words can be written here, innermost first, the script's last. */
    List<WordScope> at(CursorContext context) {
        List<WordScope> visible = new ArrayList<>(List.of(vocabulary.script()));
        for (String opener : context.blockOpeners()) {
            blockOpenedBy(opener, visible).ifPresent(block -> visible.add(0, block));
        }
        return visible;
    }

    /** The word as the first of these scopes that has it sees it, else as a word after another ({@code then}). */
    Optional<ScopedWord> find(String name, List<WordScope> visible) {
        for (WordScope s : visible) {
            WordEntry e = s.words().get(name);
            if (e != null) {
                return Optional.of(new ScopedWord(e, s));
            }
        }
        return chains().filter(s -> s.words().containsKey(name)).findFirst()
                .map(s -> new ScopedWord(s.words().get(name), s));
    }

    /** The word wherever it belongs, for a word written where it does not ({@code fence} outside a mission). */
    Optional<ScopedWord> anywhere(String name) {
        return vocabulary.scopesWith(name).stream().findFirst().map(s -> new ScopedWord(s.words().get(name), s));
    }

    /**
     * The words the statement still waits for: {@code then} after {@code waitFor { c }}, {@code run}
     * after {@code during 30}, {@code onError} after {@code watch t}; empty when the statement has none
     * pending (its word for it written, or nothing yet after the first half's word).
     */
    Optional<WordScope> pendingChain(List<ScanToken> statement) {
        for (int i = statement.size() - 1; i >= 0; i--) {
            ScanToken t = statement.get(i);
            Optional<WordScope> chain = t.kind() == ScanToken.TokenKind.WORD ? chainAfter(t.text()) : Optional.empty();
            if (chain.isPresent()) {
                List<ScanToken> after = statement.subList(i + 1, statement.size());
                boolean written = after.stream().anyMatch(a -> a.kind() == ScanToken.TokenKind.WORD && chain.get().words().containsKey(a.text()));
                return written || after.isEmpty() ? Optional.empty() : chain;
            }
        }
        return Optional.empty();
    }

    /** The chain whose words come after this word: {@code then} after {@code waitFor}. */
    Optional<WordScope> chainAfter(String word) {
        return chains().filter(s -> s.openers().contains(word)).findFirst();
    }

    private java.util.stream.Stream<WordScope> chains() {
        return vocabulary.scopes().stream().filter(s -> s.kind() == WordScope.ScopeKind.CHAIN);
    }

    private Optional<WordScope> blockOpenedBy(String word, List<WordScope> visible) {
        return find(word, visible)
                .flatMap(w -> w.entry().signatures().stream().flatMap(s -> s.params().stream())
                        .map(Param::block).filter(Objects::nonNull).findFirst())
                .flatMap(vocabulary::scopeOf)
                .filter(s -> s != vocabulary.script());
    }
}
