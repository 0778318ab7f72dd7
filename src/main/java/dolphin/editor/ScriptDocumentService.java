package dolphin.editor;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.function.BiFunction;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionParams;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidCloseTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DidSaveTextDocumentParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.SignatureHelp;
import org.eclipse.lsp4j.SignatureHelpParams;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.TextDocumentService;

/**
 * The open scripts and what the editor asks about them. Notifications update the texts on the
 * protocol's thread, in order; a request takes the text as it is then and is answered on the
 * request thread, so a slow answer (parsing a large script for a definition) holds up no change.
 */
final class ScriptDocumentService implements TextDocumentService {

    private final Map<String, OpenDocument> documents = new ConcurrentHashMap<>();
    private final DiagnosticsScheduler diagnostics;
    private final ExecutorService requests;
    private final Completions completions;
    private final Hovers hovers;
    private final CallSignatures signatures;
    private final Definitions definitions = new Definitions();
    private final QuickFixes fixes;
    private volatile boolean snippets;

    ScriptDocumentService(VisibleWords words, DiagnosticsScheduler diagnostics, QuickFixes fixes, ExecutorService requests) {
        this.diagnostics = diagnostics;
        this.fixes = fixes;
        this.requests = requests;
        this.completions = new Completions(words);
        this.hovers = new Hovers(words);
        this.signatures = new CallSignatures(words);
    }

    /** Whether completion may insert snippets: the editor said it takes them when it initialized. */
    void snippetsTaken(boolean taken) {
        this.snippets = taken;
    }

    @Override
    public void didOpen(DidOpenTextDocumentParams params) {
        var d = params.getTextDocument();
        OpenDocument document = new OpenDocument(d.getUri(), d.getVersion(), d.getText());
        documents.put(d.getUri(), document);
        diagnostics.changed(document);
    }

    @Override
    public void didChange(DidChangeTextDocumentParams params) {
        String uri = params.getTextDocument().getUri();
        OpenDocument before = documents.get(uri);
        if (before == null) {
            return;
        }
        String text = before.text();
        for (TextDocumentContentChangeEvent change : params.getContentChanges()) {
            text = applied(text, change);
        }
        OpenDocument document = new OpenDocument(uri, params.getTextDocument().getVersion(), text);
        documents.put(uri, document);
        diagnostics.changed(document);
    }

    /** The server asks for whole texts; a client that sends an edit of a range anyway gets it applied. */
    private static String applied(String text, TextDocumentContentChangeEvent change) {
        if (change.getRange() == null) {
            return change.getText();
        }
        LineMap lines = new LineMap(text);
        int start = lines.offset(change.getRange().getStart());
        int end = Math.max(start, lines.offset(change.getRange().getEnd()));
        return text.substring(0, start) + change.getText() + text.substring(end);
    }

    @Override
    public void didClose(DidCloseTextDocumentParams params) {
        String uri = params.getTextDocument().getUri();
        documents.remove(uri);
        diagnostics.closed(uri);
        fixes.forget(uri);
    }

    @Override
    public void didSave(DidSaveTextDocumentParams params) {
        // the text came with the changes; saving it changes nothing to check
    }

    @Override
    public CompletableFuture<Either<List<CompletionItem>, CompletionList>> completion(CompletionParams params) {
        return answer(params.getTextDocument().getUri(), params.getPosition(),
                (d, at) -> Either.forRight(d == null ? new CompletionList(false, List.of()) : completions.at(d, at, snippets)));
    }

    @Override
    public CompletableFuture<Hover> hover(HoverParams params) {
        return answer(params.getTextDocument().getUri(), params.getPosition(), (d, at) -> d == null ? null : hovers.at(d, at));
    }

    @Override
    public CompletableFuture<SignatureHelp> signatureHelp(SignatureHelpParams params) {
        return answer(params.getTextDocument().getUri(), params.getPosition(), (d, at) -> d == null ? null : signatures.at(d, at));
    }

    @Override
    public CompletableFuture<Either<List<? extends Location>, List<? extends LocationLink>>> definition(DefinitionParams params) {
        return answer(params.getTextDocument().getUri(), params.getPosition(), (d, at) -> {
            Location found = d == null ? null : definitions.at(d, at);
            return Either.forLeft(found == null ? List.of() : List.of(found));
        });
    }

    @Override
    public CompletableFuture<List<Either<Command, CodeAction>>> codeAction(CodeActionParams params) {
        List<Diagnostic> shown = params.getContext() == null || params.getContext().getDiagnostics() == null
                ? List.of() : params.getContext().getDiagnostics();
        return answer(params.getTextDocument().getUri(), params.getRange().getStart(),
                (d, at) -> d == null ? List.of() : fixes.at(d, params.getRange(), shown));
    }

    /** Answers on the request thread from the document as it is now (null if it is not open). */
    private <T> CompletableFuture<T> answer(String uri, Position position, BiFunction<OpenDocument, Integer, T> how) {
        OpenDocument document = documents.get(uri);
        return CompletableFuture.supplyAsync(() -> how.apply(document, document == null ? 0 : document.lines().offset(position)), requests);
    }
}
