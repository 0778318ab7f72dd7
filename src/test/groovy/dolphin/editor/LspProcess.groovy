package dolphin.editor

import groovy.json.JsonOutput
import groovy.json.JsonSlurper
import java.nio.charset.StandardCharsets
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit

/**
 * {@code dolphin lsp} as an editor starts it: a process of its own ({@code java -cp <this JVM's
 * class path> dolphin.cli.Main lsp}), spoken to in the protocol's frames on its standard input and
 * output. Its standard error goes to a file, shown when something fails.
 */
final class LspProcess implements AutoCloseable {

    static final long DEADLINE_SECONDS = 30

    final Process process
    final Path stderr = Files.createTempFile('dolphin-lsp-', '.log')
    private final InputStream out
    private int nextId = 1

    LspProcess() {
        String java = Path.of(System.getProperty('java.home'), 'bin', 'java').toString()
        process = new ProcessBuilder(java, '-cp', System.getProperty('java.class.path'), 'dolphin.cli.Main', 'lsp')
                .redirectError(stderr.toFile()).start()
        out = new BufferedInputStream(process.inputStream)
    }

    /** Sends a request; its id. */
    int request(String method, Object params) {
        int id = nextId++
        send([jsonrpc: '2.0', id: id, method: method, params: params])
        id
    }

    void notify(String method, Object params) {
        send([jsonrpc: '2.0', method: method, params: params])
    }

    /** Opens a script, as an editor does when it shows one. */
    void open(String uri, String text) {
        notify('textDocument/didOpen', [textDocument: [uri: uri, languageId: 'dolphin', version: 1, text: text]])
    }

    /** Opens a script and waits for its check: the publishDiagnostics message. */
    Map openChecked(String uri, String text) {
        open(uri, text)
        next { it.method == 'textDocument/publishDiagnostics' }
    }

    private void send(Map message) {
        sendRaw(JsonOutput.toJson(message))
    }

    /** A frame with this body, JSON or not. */
    void sendRaw(String text) {
        byte[] body = text.getBytes(StandardCharsets.UTF_8)
        process.outputStream.write("Content-Length: ${body.length}\r\n\r\n".getBytes(StandardCharsets.US_ASCII))
        process.outputStream.write(body)
        process.outputStream.flush()
    }

    /** The next message the server sends that the test wants, skipping others; fails at the deadline or the output's end. */
    Map next(Closure<Boolean> wanted) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(DEADLINE_SECONDS)
        while (System.nanoTime() < deadline) {
            Map m = read()
            assert m != null: "the server's output ended; its log:\n${log()}"
            if (wanted(m)) {
                return m
            }
        }
        throw new AssertionError("no such message within ${DEADLINE_SECONDS} s; the server's log:\n${log()}")
    }

    /** One framed message, or null at the end of the output; anything else on the output fails. */
    Map read() {
        String header = headerLine()
        if (header == null) {
            return null
        }
        assert header ==~ /Content-Length: \d+/: "not a protocol header on the server's output: '${header}'"
        int length = header.split(': ')[1] as int
        assert headerLine() == '': 'a header block ends with an empty line'
        byte[] body = out.readNBytes(length)
        assert body.length == length: 'the output ended inside a message'
        new JsonSlurper().parseText(new String(body, StandardCharsets.UTF_8)) as Map
    }

    private String headerLine() {
        def line = new ByteArrayOutputStream()
        int c
        while ((c = out.read()) >= 0) {
            if (c == '\n' as char) {
                String s = line.toString('US-ASCII')
                assert s.endsWith('\r'): "a header line ends with CRLF: '${s}'"
                return s.substring(0, s.length() - 1)
            }
            line.write(c)
        }
        assert line.size() == 0: "bytes on the server's output that are no message: '${line.toString('UTF-8')}'"
        null
    }

    void initialize(Map capabilities = [:]) {
        int id = request('initialize', [processId: null, rootUri: null, capabilities: capabilities])
        next { it.id == id }
        notify('initialized', [:])
    }

    /** Closes the server's input, as an editor that quits or crashes does. */
    void closeInput() {
        process.outputStream.close()
    }

    /** The exit code, waiting up to the deadline. */
    int exitCode() {
        assert process.waitFor(DEADLINE_SECONDS, TimeUnit.SECONDS): "the server did not end within ${DEADLINE_SECONDS} s; its log:\n${log()}"
        process.exitValue()
    }

    String log() {
        Files.readString(stderr)
    }

    @Override
    void close() {
        process.destroyForcibly()
        process.waitFor(DEADLINE_SECONDS, TimeUnit.SECONDS)
        Files.deleteIfExists(stderr)
    }
}
