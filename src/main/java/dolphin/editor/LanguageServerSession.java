package dolphin.editor;

import java.io.InputStream;
import java.io.OutputStream;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Serves one client over a pair of streams (a process's standard input and output) until it leaves. */
public final class LanguageServerSession {

    private static final Logger LOG = LoggerFactory.getLogger(LanguageServerSession.class);

    private LanguageServerSession() {
    }

    /**
     * Serves until the client says {@code exit} (its exit code: 0 after {@code shutdown}, 1 without)
     * or closes its end of the input (0: a client that went away ends the server cleanly).
     */
    public static int serve(DolphinLanguageServer server, InputStream in, OutputStream out) throws InterruptedException {
        Launcher<LanguageClient> launcher = LSPLauncher.createServerLauncher(server, in, out);
        server.connect(launcher.getRemoteProxy());
        Future<Void> listening = launcher.startListening();
        Thread input = new Thread(() -> {
            try {
                listening.get();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (ExecutionException e) {
                LOG.warn("reading the client's messages failed", e.getCause());
            }
            server.close();
            server.exited().complete(0);
        }, "dolphin-lsp-input");
        input.setDaemon(true);
        input.start();
        try {
            return server.exited().get();
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        } finally {
            server.close();
        }
    }
}
