package dolphin.editor;

import dolphin.core.Clock;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CodeActionKind;
import org.eclipse.lsp4j.CodeActionOptions;
import org.eclipse.lsp4j.CompletionCapabilities;
import org.eclipse.lsp4j.CompletionItemCapabilities;
import org.eclipse.lsp4j.CompletionOptions;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.ServerInfo;
import org.eclipse.lsp4j.SignatureHelpOptions;
import org.eclipse.lsp4j.TextDocumentClientCapabilities;
import org.eclipse.lsp4j.TextDocumentSyncKind;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageClientAware;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.lsp4j.services.TextDocumentService;
import org.eclipse.lsp4j.services.WorkspaceService;

/**
 * The Dolphin language server (docs/editors.md): diagnostics as the user types, with their quick
 * fixes, completion, hover, signature help and go to definition for {@code .dolphin} scripts, from
 * the language's own vocabulary. {@link #exited()} gives the process's exit code: 0 after {@code shutdown} then
 * {@code exit}, 1 after {@code exit} alone, as the protocol says.
 */
public final class DolphinLanguageServer implements LanguageServer, LanguageClientAware, AutoCloseable {

    /** How long a script must stay unchanged before it is checked. */
    public static final Duration QUIET_PERIOD = Duration.ofMillis(250);

    private final DiagnosticsScheduler diagnostics;
    private final ExecutorService requests = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "dolphin-lsp-requests");
        t.setDaemon(true);
        return t;
    });
    private final ScriptDocumentService documents;
    private final IgnoredWorkspaceEvents workspace = new IgnoredWorkspaceEvents();
    private final CompletableFuture<Integer> exited = new CompletableFuture<>();
    private volatile LanguageClient client;
    private volatile boolean shutdownRequested;

    /** A server that checks with the MAVLink platform's words, as {@code dolphin check} does. */
    public DolphinLanguageServer(Clock clock) {
        this(clock, QUIET_PERIOD, ScriptChecker.withMavlinkWords());
    }

    DolphinLanguageServer(Clock clock, Duration quiet, ScriptChecker checker) {
        QuickFixes fixes = new QuickFixes();
        this.diagnostics = new DiagnosticsScheduler(clock, quiet, d -> fixes.remember(d, checker.check(d)), this::publish);
        this.documents = new ScriptDocumentService(new VisibleWords(checker.engine().vocabulary()), diagnostics, fixes, requests);
    }

    @Override
    public void connect(LanguageClient languageClient) {
        this.client = languageClient;
        diagnostics.start();
    }

    private void publish(PublishDiagnosticsParams params) {
        LanguageClient c = client;
        if (c != null) {
            c.publishDiagnostics(params);
        }
    }

    @Override
    public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
        documents.snippetsTaken(takesSnippets(params.getCapabilities()));
        ServerCapabilities capabilities = new ServerCapabilities();
        capabilities.setTextDocumentSync(TextDocumentSyncKind.Full);
        capabilities.setCompletionProvider(new CompletionOptions(false, List.of(".")));
        capabilities.setHoverProvider(true);
        capabilities.setSignatureHelpProvider(new SignatureHelpOptions(List.of("(", ",", " ")));
        capabilities.setDefinitionProvider(true);
        capabilities.setCodeActionProvider(new CodeActionOptions(List.of(CodeActionKind.QuickFix)));
        String version = DolphinLanguageServer.class.getPackage().getImplementationVersion();
        return CompletableFuture.completedFuture(new InitializeResult(capabilities,
                new ServerInfo("dolphin", version == null ? "development build" : version)));
    }

    /** Whether the editor said it takes snippets in completion items; those that do not get plain words. */
    private static boolean takesSnippets(ClientCapabilities capabilities) {
        return Optional.ofNullable(capabilities).map(ClientCapabilities::getTextDocument)
                .map(TextDocumentClientCapabilities::getCompletion).map(CompletionCapabilities::getCompletionItem)
                .map(CompletionItemCapabilities::getSnippetSupport).orElse(false);
    }

    @Override
    public CompletableFuture<Object> shutdown() {
        shutdownRequested = true;
        return CompletableFuture.completedFuture(null);
    }

    @Override
    public void exit() {
        close();
        exited.complete(shutdownRequested ? 0 : 1);
    }

    /** Completes with the exit code when the client says {@code exit}. */
    public CompletableFuture<Integer> exited() {
        return exited;
    }

    @Override
    public TextDocumentService getTextDocumentService() {
        return documents;
    }

    @Override
    public WorkspaceService getWorkspaceService() {
        return workspace;
    }

    @Override
    public void close() {
        diagnostics.close();
        requests.shutdownNow();
    }
}
