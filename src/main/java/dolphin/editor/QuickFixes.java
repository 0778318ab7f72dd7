package dolphin.editor;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.jsonrpc.messages.Either;

/**
 * The quick fixes of each open script's last check, kept by the server rather than sent with the
 * diagnostics, so any client gets them: a client asks for code actions with the diagnostics it
 * shows, each found again here by its range and message. Fixes are offered only for the text they
 * were found in (the same {@link OpenDocument}); once it has changed, the next check brings new ones.
 */
final class QuickFixes {

    private record Checked(OpenDocument document, List<FixableDiagnostic> found) {
    }

    private final Map<String, Checked> checked = new ConcurrentHashMap<>();

    /** Keeps the fixes of a check; its diagnostics, to publish. */
    List<Diagnostic> remember(OpenDocument document, List<FixableDiagnostic> found) {
        checked.put(document.uri(), new Checked(document, List.copyOf(found)));
        return found.stream().map(FixableDiagnostic::diagnostic).toList();
    }

    void forget(String uri) {
        checked.remove(uri);
    }

    /**
     * The fixes of the diagnostics the client names, or, when it names none, of those that touch the
     * range; none when the document has changed since its check.
     */
    List<Either<Command, CodeAction>> at(OpenDocument document, Range range, List<Diagnostic> shown) {
        Checked c = checked.get(document.uri());
        if (c == null || c.document() != document) {
            return List.of();
        }
        return c.found().stream()
                .filter(f -> shown.isEmpty() ? touches(f.diagnostic().getRange(), range)
                        : shown.stream().anyMatch(d -> same(d, f.diagnostic())))
                .flatMap(f -> f.fixes().stream())
                .map(Either::<Command, CodeAction>forRight)
                .toList();
    }

    private static boolean same(Diagnostic shown, Diagnostic found) {
        return Objects.equals(shown.getRange(), found.getRange()) && shown.getMessage() != null
                && Objects.equals(shown.getMessage().getLeft(), found.getMessage().getLeft());
    }

    private static boolean touches(Range a, Range b) {
        return !before(a.getEnd(), b.getStart()) && !before(b.getEnd(), a.getStart());
    }

    private static boolean before(Position p, Position q) {
        return p.getLine() < q.getLine() || p.getLine() == q.getLine() && p.getCharacter() < q.getCharacter();
    }
}
