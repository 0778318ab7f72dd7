package dolphin.cli;

import dolphin.core.SystemClock;
import dolphin.editor.DolphinLanguageServer;
import dolphin.editor.LanguageServerSession;
import java.io.PrintStream;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;

/** {@code dolphin lsp}: the language server for editors, on standard input and output (docs/editors.md). */
@Command(name = "lsp", mixinStandardHelpOptions = true,
        description = {"Serves the Language Server Protocol on standard input and output, for editors: "
                + "diagnostics as you type, completion, hover, signature help and go to definition for .dolphin scripts.",
                "Logs go to standard error. Exit 0 when the editor shuts the server down or closes its input, "
                        + "1 when it exits without shutting it down first."})
final class LspCommand implements Callable<Integer> {

    @Override
    public Integer call() throws InterruptedException {
        PrintStream protocol = System.out;
        // only the protocol's messages may reach standard output: anything else printed goes to standard error
        System.setOut(System.err);
        return LanguageServerSession.serve(new DolphinLanguageServer(SystemClock.REAL), System.in, protocol);
    }
}
