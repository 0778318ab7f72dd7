package dolphin.editor;

import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.ParameterInformation;
import org.eclipse.lsp4j.SignatureHelp;
import org.eclipse.lsp4j.SignatureInformation;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.jsonrpc.messages.Tuple;

/**
 * The forms of the word being called at the cursor, with the argument the cursor is on: inside
 * {@code word(...)}, or after {@code word } in Groovy's command syntax ({@code goPos 41.1, -8.6, 120},
 * also {@code x = word ...} and the second word of {@code waitFor { c } then t}). The argument is the
 * number of commas before the cursor at the call's own level.
 */
final class CallSignatures {

    private final VisibleWords words;

    CallSignatures(VisibleWords words) {
        this.words = words;
    }

    SignatureHelp at(OpenDocument document, int offset) {
        CursorContext context = CodeScanner.scan(document.text(), offset);
        if (!context.inCode()) {
            return null;
        }
        List<WordScope> visible = words.at(context);
        List<ScanFrame> frames = context.frames();
        for (int i = frames.size() - 1; i >= 0; i--) {
            ScanFrame f = frames.get(i);
            if (f.kind == ScanFrame.FrameKind.INTERPOLATION) {
                return null;
            }
            if (f.kind == ScanFrame.FrameKind.SCRIPT || f.kind == ScanFrame.FrameKind.BRACE) {
                return command(f.statement(), offset, visible);
            }
            // a parenthesis after a word calls it; a list, or a parenthesis after none, is an argument of the call around it
            Optional<ScopedWord> called = f.kind == ScanFrame.FrameKind.PAREN && f.opener != null
                    ? words.find(f.opener, visible) : Optional.empty();
            if (called.isPresent()) {
                return help(called.get().entry(), commas(f.statement(), 0));
            }
        }
        return null;
    }

    /** Command syntax: the statement's first word (after {@code x =}), or the second word of a two-word instruction. */
    private SignatureHelp command(List<ScanToken> statement, int offset, List<WordScope> visible) {
        int first = statement.size() >= 2 && statement.get(0).kind() == ScanToken.TokenKind.WORD
                && statement.get(1).is(ScanToken.TokenKind.SYMBOL, "=") ? 2 : 0;
        if (statement.size() <= first || statement.get(first).kind() != ScanToken.TokenKind.WORD) {
            return null;
        }
        ScanToken word = statement.get(first);
        ScanToken next = statement.size() > first + 1 ? statement.get(first + 1) : null;
        boolean argumentsFollow = next == null ? offset > word.end()
                : next.start() > word.end() && (next.kind() != ScanToken.TokenKind.SYMBOL || next.text().equals("-"));
        if (!argumentsFollow) {
            return null;
        }
        int call = first;
        for (int i = first + 1; i < statement.size(); i++) {
            ScanToken t = statement.get(i);
            if (t.kind() == ScanToken.TokenKind.WORD && isSecondWord(statement.subList(first, i), t.text())) {
                call = i;
            }
        }
        ScanToken called = statement.get(call);
        if (call > first && called.end() == offset) {
            return null;
        }
        int argument = commas(statement, call + 1);
        return words.find(called.text(), visible).map(w -> help(w.entry(), argument)).orElse(null);
    }

    private boolean isSecondWord(List<ScanToken> before, String word) {
        return before.stream().anyMatch(b -> b.kind() == ScanToken.TokenKind.WORD
                && words.chainAfter(b.text()).map(c -> c.words().containsKey(word)).orElse(false));
    }

    private static int commas(List<ScanToken> tokens, int from) {
        int n = 0;
        for (int i = from; i < tokens.size(); i++) {
            if (tokens.get(i).is(ScanToken.TokenKind.SYMBOL, ",")) {
                n++;
            }
        }
        return n;
    }

    /** The word's forms; the active one is the first with a parameter at the argument, else the longest. */
    private static SignatureHelp help(WordEntry word, int argument) {
        List<SignatureInformation> forms = new ArrayList<>();
        int active = -1;
        int longest = 0;
        int longestSize = -1;
        for (String usage : word.usages()) {
            List<ParameterInformation> params = new ArrayList<>();
            for (int[] s : UsageParameters.of(usage, word.name())) {
                String name = usage.substring(s[0], s[1]).replaceAll("[{}. ]", "");
                String unit = WordText.unitOf(word, name);
                ParameterInformation p = new ParameterInformation();
                p.setLabel(Either.forRight(new Tuple.Two<>(s[0], s[1])));
                if (!unit.isEmpty()) {
                    p.setDocumentation(Either.forLeft(name + ": " + unit));
                }
                params.add(p);
            }
            SignatureInformation form = new SignatureInformation(usage, new MarkupContent(MarkupKind.MARKDOWN, word.description()), params);
            form.setActiveParameter(Math.min(argument, Math.max(0, params.size() - 1)));
            if (active < 0 && params.size() > argument) {
                active = forms.size();
            }
            if (params.size() > longestSize) {
                longest = forms.size();
                longestSize = params.size();
            }
            forms.add(form);
        }
        return new SignatureHelp(forms, active >= 0 ? active : longest, argument);
    }
}
