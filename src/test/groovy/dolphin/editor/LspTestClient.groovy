package dolphin.editor

import dolphin.core.Clock
import dolphin.core.ManualClock
import java.time.Duration
import java.util.concurrent.CompletableFuture
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import org.eclipse.lsp4j.ClientCapabilities
import org.eclipse.lsp4j.CodeAction
import org.eclipse.lsp4j.CodeActionContext
import org.eclipse.lsp4j.CodeActionParams
import org.eclipse.lsp4j.CompletionCapabilities
import org.eclipse.lsp4j.CompletionItem
import org.eclipse.lsp4j.CompletionItemCapabilities
import org.eclipse.lsp4j.CompletionList
import org.eclipse.lsp4j.CompletionParams
import org.eclipse.lsp4j.DefinitionParams
import org.eclipse.lsp4j.Diagnostic
import org.eclipse.lsp4j.DidChangeTextDocumentParams
import org.eclipse.lsp4j.DidCloseTextDocumentParams
import org.eclipse.lsp4j.DidOpenTextDocumentParams
import org.eclipse.lsp4j.Hover
import org.eclipse.lsp4j.HoverParams
import org.eclipse.lsp4j.InitializeParams
import org.eclipse.lsp4j.InitializeResult
import org.eclipse.lsp4j.InitializedParams
import org.eclipse.lsp4j.Location
import org.eclipse.lsp4j.MessageActionItem
import org.eclipse.lsp4j.MessageParams
import org.eclipse.lsp4j.Position
import org.eclipse.lsp4j.PublishDiagnosticsParams
import org.eclipse.lsp4j.Range
import org.eclipse.lsp4j.ShowMessageRequestParams
import org.eclipse.lsp4j.SignatureHelp
import org.eclipse.lsp4j.SignatureHelpParams
import org.eclipse.lsp4j.TextDocumentClientCapabilities
import org.eclipse.lsp4j.TextDocumentContentChangeEvent
import org.eclipse.lsp4j.TextDocumentIdentifier
import org.eclipse.lsp4j.TextDocumentItem
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier
import org.eclipse.lsp4j.launch.LSPLauncher
import org.eclipse.lsp4j.services.LanguageClient
import org.eclipse.lsp4j.services.LanguageServer

/**
 * LSP4J's client side talking to a server in this process over piped streams (no sockets): it
 * records what the server publishes and waits for it with a deadline. The server's clock is
 * virtual by default (an auto-advancing ManualClock: the quiet period passes at once, no real time).
 */
final class LspTestClient implements LanguageClient, AutoCloseable {

    static final long DEADLINE_SECONDS = 20

    final LinkedBlockingQueue<PublishDiagnosticsParams> published = new LinkedBlockingQueue<>()
    final DolphinLanguageServer server
    final PipedOutputStream toServer = new PipedOutputStream()
    final PipedOutputStream toClient = new PipedOutputStream()
    final CompletableFuture<Integer> served = new CompletableFuture<>()
    LanguageServer remote
    InitializeResult initialized

    LspTestClient(Clock clock = ManualClock.autoAdvancing(), Duration quiet = DolphinLanguageServer.QUIET_PERIOD,
                  ClientCapabilities capabilities = new ClientCapabilities()) {
        server = new DolphinLanguageServer(clock, quiet, ScriptChecker.withMavlinkWords())
        def serverIn = new PipedInputStream(toServer, 1 << 20)
        def clientIn = new PipedInputStream(toClient, 1 << 20)
        Thread.start('test: dolphin lsp') {
            try {
                served.complete(LanguageServerSession.serve(server, serverIn, toClient))
            } catch (Throwable t) {
                served.completeExceptionally(t)
            }
        }
        def launcher = LSPLauncher.createClientLauncher(this, clientIn, toServer)
        launcher.startListening()
        remote = launcher.remoteProxy
        initialized = remote.initialize(new InitializeParams(capabilities: capabilities)).get(DEADLINE_SECONDS, TimeUnit.SECONDS)
        remote.initialized(new InitializedParams())
    }

    /** A client that says, as VS Code does, that it takes snippets in completion items. */
    static LspTestClient takingSnippets() {
        def completion = new CompletionCapabilities(new CompletionItemCapabilities(true))
        new LspTestClient(ManualClock.autoAdvancing(), DolphinLanguageServer.QUIET_PERIOD,
                new ClientCapabilities(null, new TextDocumentClientCapabilities(completion: completion), null))
    }

    void open(String uri, String text) {
        remote.textDocumentService.didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, 'dolphin', 1, text)))
    }

    void change(String uri, int version, String text) {
        remote.textDocumentService.didChange(new DidChangeTextDocumentParams(new VersionedTextDocumentIdentifier(uri, version),
                [new TextDocumentContentChangeEvent(text)]))
    }

    void closeDocument(String uri) {
        remote.textDocumentService.didClose(new DidCloseTextDocumentParams(new TextDocumentIdentifier(uri)))
    }

    /** The diagnostics published for this version of the document (or, with null, for its closing). */
    PublishDiagnosticsParams diagnostics(String uri, Integer version, long seconds = DEADLINE_SECONDS) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds)
        while (true) {
            def p = published.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS)
            assert p != null: "no diagnostics for ${uri} version ${version} within ${seconds} s"
            if (p.uri == uri && p.version == version) {
                return p
            }
        }
    }

    /** The text's position of the first '|', and the text without it. */
    static List cursor(String marked) {
        int at = marked.indexOf('|')
        String before = marked.substring(0, at)
        [marked.substring(0, at) + marked.substring(at + 1), new Position(before.count('\n'), at - before.lastIndexOf('\n') - 1)]
    }

    List<CompletionItem> complete(String uri, Position p) {
        completionList(uri, p).items
    }

    CompletionList completionList(String uri, Position p) {
        remote.textDocumentService.completion(new CompletionParams(new TextDocumentIdentifier(uri), p))
                .get(DEADLINE_SECONDS, TimeUnit.SECONDS).getRight()
    }

    Hover hover(String uri, Position p) {
        remote.textDocumentService.hover(new HoverParams(new TextDocumentIdentifier(uri), p)).get(DEADLINE_SECONDS, TimeUnit.SECONDS)
    }

    SignatureHelp signatureHelp(String uri, Position p) {
        remote.textDocumentService.signatureHelp(new SignatureHelpParams(new TextDocumentIdentifier(uri), p))
                .get(DEADLINE_SECONDS, TimeUnit.SECONDS)
    }

    List<Location> definition(String uri, Position p) {
        remote.textDocumentService.definition(new DefinitionParams(new TextDocumentIdentifier(uri), p))
                .get(DEADLINE_SECONDS, TimeUnit.SECONDS).getLeft() as List<Location>
    }

    /** The code actions for a range, with the diagnostics the client shows there. */
    List<CodeAction> codeActions(String uri, Range range, List<Diagnostic> shown) {
        remote.textDocumentService.codeAction(new CodeActionParams(new TextDocumentIdentifier(uri), range, new CodeActionContext(shown)))
                .get(DEADLINE_SECONDS, TimeUnit.SECONDS).collect { it.getRight() }
    }

    /** Closes the client's end of the server's input, as an editor that goes away does; the server's exit code. */
    int disconnect() {
        toServer.close()
        served.get(DEADLINE_SECONDS, TimeUnit.SECONDS)
    }

    @Override
    void close() {
        if (!served.isDone()) {
            remote.shutdown().get(DEADLINE_SECONDS, TimeUnit.SECONDS)
            remote.exit()
            served.get(DEADLINE_SECONDS, TimeUnit.SECONDS)
        }
        toServer.close()
        toClient.close()
    }

    @Override
    void publishDiagnostics(PublishDiagnosticsParams diagnostics) {
        published.add(diagnostics)
    }

    @Override
    void telemetryEvent(Object object) {
    }

    @Override
    void showMessage(MessageParams message) {
    }

    @Override
    CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams request) {
        CompletableFuture.completedFuture(null)
    }

    @Override
    void logMessage(MessageParams message) {
    }
}
