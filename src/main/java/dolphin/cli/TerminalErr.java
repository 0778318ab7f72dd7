package dolphin.cli;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;

/**
 * Standard error shown through the live screen while a run draws its table: log lines (vehicle
 * discovery, the vehicles' STATUSTEXT) written straight to the terminal would land between two
 * redraws and leave stale rows behind. Only when standard output and standard error are the same
 * terminal, so that `2>file` still gets the log.
 */
final class TerminalErr implements AutoCloseable {

    private final PrintStream original = System.err;
    private final Lines lines;

    private TerminalErr(Consumer<String> sink) {
        lines = new Lines(sink);
        System.setErr(new PrintStream(lines, true, StandardCharsets.UTF_8));
    }

    /** Sends standard error's lines to {@code sink} until closed, if both streams are one terminal; else does nothing. */
    static AutoCloseable captureIfShared(Consumer<String> sink) {
        return sameTerminal() ? new TerminalErr(sink) : () -> { };
    }

    /** Linux only: both descriptors lead to the same terminal device. */
    static boolean sameTerminal() {
        try {
            Path out = Files.readSymbolicLink(Path.of("/proc/self/fd/1"));
            Path err = Files.readSymbolicLink(Path.of("/proc/self/fd/2"));
            return out.equals(err) && (out.startsWith("/dev/pts") || out.toString().startsWith("/dev/tty"));
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return false;
        }
    }

    @Override
    public void close() {
        System.err.flush();
        System.setErr(original);
        lines.close();
    }

    /** Bytes to whole lines; a last line without its newline is handed over on close. */
    static final class Lines extends OutputStream {
        private final Consumer<String> sink;
        private final ByteArrayOutputStream line = new ByteArrayOutputStream();

        Lines(Consumer<String> sink) {
            this.sink = sink;
        }

        @Override
        public synchronized void write(int b) {
            if (b == '\n') {
                emit();
            } else if (b != '\r') {
                line.write(b);
            }
        }

        @Override
        public synchronized void close() {
            if (line.size() > 0) {
                emit();
            }
        }

        private void emit() {
            sink.accept(line.toString(StandardCharsets.UTF_8));
            line.reset();
        }
    }
}
