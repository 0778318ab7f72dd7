package dolphin.docs

import dolphin.cli.Main
import groovy.json.JsonSlurper
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CompletableFuture
import java.util.concurrent.TimeUnit
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

/**
 * Every fenced code block in docs/*.md is executed or checked as docs/README.md says, so no example
 * in the documentation can rot. One feature per block, in document order: a text or json block may
 * check the output or the files of the block before it in the same document.
 */
class DocsExamplesSpec extends Specification {

    static final Path DOCS = Path.of('docs')
    static final Set<String> KINDS = ['groovy', 'sh', 'java', 'text', 'json', 'lua', 'elisp'] as Set
    static final Set<String> DIRECTIVES = ['run', 'mission', 'check', 'exit', 'expect', 'output', 'file'] as Set

    /** One fenced block: where it is, its info string, its text and the directives just above it. */
    static final class Block {
        String doc
        int line
        String kind
        String text
        List<List<String>> directives

        List<String> all(String name) { directives.findAll { it[0] == name }.collect { it[1] } }

        String one(String name) { all(name) ? all(name)[0] : null }

        boolean has(String name) { directives.any { it[0] == name } }

        String toString() { "${doc}:${line} ${kind}" + (directives ? ' ' + directives.collect { it[1] ? "${it[0]}: ${it[1]}" : it[0] }.join(', ') : '') }
    }

    /** The fenced blocks of every docs/*.md, in file and line order. */
    static List<Block> blocks() {
        List<Block> found = []
        Files.list(DOCS).withCloseable { it.filter { it.toString().endsWith('.md') }.sorted().toList() }.each { Path file ->
            List<String> lines = Files.readAllLines(file)
            for (int i = 0; i < lines.size(); i++) {
                def open = lines[i] =~ /^```(.*)$/
                if (!open.matches()) {
                    continue
                }
                int close = lines.findIndexOf(i + 1) { it == '```' }
                assert close > i: "${file}:${i + 1}: a code block that is never closed"
                List<List<String>> directives = []
                for (int j = i - 1; j >= 0 && lines[j].startsWith('<!--'); j--) {
                    def d = lines[j] =~ /^<!-- ([a-z]+)(?::\s*(.*?))?\s*-->$/
                    assert d.matches(): "${file}:${j + 1}: a directive is '<!-- name -->' or '<!-- name: value -->'"
                    directives.add(0, [d.group(1), d.group(2)])
                }
                found << new Block(doc: file.toString(), line: i + 1, kind: open.group(1).trim(),
                        text: lines.subList(i + 1, close).join('\n') + '\n', directives: directives)
                i = close
            }
        }
        found
    }

    /** Per document: a working directory for the files its commands write, and the last block's output. */
    @Shared
    Map<String, Path> workDirs = [:]
    @Shared
    Map<String, String> lastOutput = [:]

    def cleanupSpec() {
        workDirs.values().each { dir -> dir.toFile().deleteDir() }
    }

    Path workDir(Block b) {
        workDirs.computeIfAbsent(b.doc) { Files.createTempDirectory('dolphin-docs-') }
    }

    /** `dolphin ARGS` in this process, as Main.main would run it but with captured output. */
    static Map dolphin(List<String> args, int seconds = 60) {
        def out = new StringWriter()
        def err = new StringWriter()
        def code = new CompletableFuture<Integer>()
        def thread = Thread.start("docs: dolphin ${args[0]}") {
            try {
                code.complete(Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(args as String[]))
            } catch (Throwable t) {
                code.completeExceptionally(t)
            }
        }
        try {
            return [code: code.get(seconds, TimeUnit.SECONDS), out: out.toString(), err: err.toString()]
        } catch (java.util.concurrent.TimeoutException e) {
            thread.interrupt()
            throw new AssertionError("dolphin ${args.join(' ')} did not end within ${seconds} s; output so far:\n${out}\n${err}")
        }
    }

    def "every block in docs/*.md has a known kind and known directives"() {
        when:
        List<String> wrong = blocks().collectMany { b ->
            (b.kind in KINDS ? [] : ["${b}: unknown info string '${b.kind}'; known: ${KINDS.join(', ')} (docs/README.md)"])
                    + b.directives.findAll { !(it[0] in DIRECTIVES) }.collect { "${b}: unknown directive '${it[0]}'" }
        }*.toString()

        then:
        wrong == []
    }

    @Timeout(120)
    def "#block"() {
        expect:
        check(block)

        where:
        block << blocks()
    }

    boolean check(Block b) {
        Map<String, Closure> checks = [groovy: this.&script, sh: this.&commands, java: this.&javaSource,
                                       text: this.&sample, json: this.&jsonSample, lua: this.&neovimConfig,
                                       elisp: this.&emacsConfig]
        assert checks.keySet() == KINDS
        assert b.kind in KINDS: "${b}: unknown info string '${b.kind}' (docs/README.md)"
        checks[b.kind].call(b)
        true
    }

    /** A groovy block: Dolphin script code, checked (default), run against the simulated fleet, or dry-run. */
    void script(Block b) {
        allow(b, 'run', 'mission', 'check', 'exit', 'expect')
        assert [b.has('run'), b.has('mission'), b.has('check')].count(true) <= 1: "${b}: at most one of run, mission, check"
        Path file = workDir(b).resolve("${Path.of(b.doc).fileName.toString() - '.md'}-${b.line}.dolphin")
        Files.writeString(file, b.text)
        List<String> args
        if (b.has('run')) {
            args = ['run', file.toString()] + b.one('run').split(/\s+/).toList()
            assert args.contains('--sim'): "${b}: a run directive gives --sim N: the examples never talk to real vehicles"
        } else if (b.has('mission')) {
            args = ['mission', file.toString()]
        } else {
            args = ['check', file.toString()]
        }
        def r = dolphin(args)
        finish(b, r, (b.one('exit') ?: '0') as int)
    }

    /** Checks the exit code and the expect lines, and keeps the output for an output block below. */
    void finish(Block b, Map r, int exit) {
        String output = r.out + r.err
        assert r.code == exit: "${b}: exit code ${r.code}, expected ${exit}; output:\n${output}"
        int at = 0
        b.all('expect').each { String text ->
            int i = output.indexOf(text, at)
            assert i >= 0: "${b}: expected '${text}' (after what the earlier expect lines matched) in the output:\n${output}"
            at = i + text.length()
        }
        lastOutput[b.doc] = output
    }

    /**
     * An sh block: each line is one `./dolphin` command (a trailing `# comment` may say `exit N`) or
     * `echo 'TEXT' > FILE`. `dolphin sim` runs in the background for the rest of the block; a
     * `dolphin run` without --sim talks to it; tcp and serial links lead nowhere here.
     */
    void commands(Block b) {
        allow(b, 'expect')
        int port = new DatagramSocket(0).withCloseable { it.localPort }
        List<Thread> sims = []
        StringBuilder output = new StringBuilder()
        try {
            b.text.readLines().findAll { it.trim() && !it.trim().startsWith('#') }.each { String line ->
                def m = line =~ /^(.*?)(?:\s+#\s*(.*))?$/
                m.matches()
                List<String> words = words(m.group(1).trim())
                String comment = m.group(2) ?: ''
                if (words[0] == 'echo') {
                    assert words.size() == 4 && words[2] == '>': "${b}: echo 'TEXT' > FILE, got: ${line}"
                    Files.writeString(workDir(b).resolve(words[3]), words[1] + '\n')
                    return
                }
                assert words[0] == './dolphin': "${b}: sh blocks hold ./dolphin commands and echo lines only, got: ${line}"
                List<String> args = localise(b, words.drop(1), port)
                if (args[0] == 'sim') {
                    sims << Thread.start("docs: dolphin sim") { dolphin(args, 600) }
                    return
                }
                boolean nowhere = args.any { it.startsWith('tcp:') || it.startsWith('serial:') }
                def exitComment = comment =~ /\bexit (\d)\b/
                int exit = exitComment.find() ? exitComment.group(1) as int : 0
                if (args[0] == 'run' && !args.contains('--sim') && !nowhere) {
                    assert sims || exit != 0: "${b}: '${line}' needs vehicles: a './dolphin sim' line before it, or --sim N"
                    if (!args.contains('--link')) {
                        args += ['--link', "udpin:127.0.0.1:${port}".toString()]
                    }
                }
                def r = dolphin(args)
                output << r.out << r.err
                if (nowhere) {
                    assert r.code == 2 && r.err =~ /^dolphin run: (cannot connect to tcp:|no serial port|cannot open serial port)/:
                            "${b}: '${line}' should fail only because the vehicle is not there (exit 2); got ${r.code}:\n${r.out}${r.err}"
                } else {
                    assert r.code == exit: "${b}: '${line}' exit code ${r.code}, expected ${exit}; output:\n${r.out}${r.err}"
                }
            }
        } finally {
            sims.each { it.interrupt(); it.join(10_000) }
        }
        finish(b, [code: 0, out: output.toString(), err: ''], 0)
    }

    /**
     * The arguments as they run here: files written (--out, --tlog) and read (--signing-key, the
     * simulated fleet's --config and --sim-config) in the document's working directory; the default port 14559 replaced by a free one, and the web view's
     * port by 0 (a free one, on loopback); tcp links aimed at a closed port and serial links at a
     * device that does not exist.
     */
    List<String> localise(Block b, List<String> args, int port) {
        List<String> result = []
        args.eachWithIndex { String a, int i ->
            String before = i > 0 ? args[i - 1] : ''
            if (before in ['--out', '--tlog', '--signing-key', '--config', '--sim-config']) {
                result << workDir(b).resolve(a).toString()
            } else if (before == '--web') {
                result << '0'
            } else if (a.startsWith('tcp:')) {
                int closed = new ServerSocket(0).withCloseable { it.localPort }
                result << "tcp:127.0.0.1:${closed}".toString()
            } else if (a.startsWith('serial:')) {
                result << "serial:${workDir(b).resolve('no-such-device')}:${a.tokenize(':').last()}".toString()
            } else {
                result << a.replace(':14559', ":${port}")
            }
        }
        if (result[0] == 'sim' && !result.contains('--link')) {
            result += ['--link', "udpout:127.0.0.1:${port}".toString()]
        }
        result
    }

    /** Splits a command line into words; single or double quotes group words. */
    static List<String> words(String line) {
        def m = line =~ /'([^']*)'|"([^"]*)"|(\S+)/
        m.collect { it[1] ?: it[2] ?: it[3] }
    }

    /** A java block is a test source file, verbatim; a class with main is run and prints the block's output. */
    void javaSource(Block b) {
        allow(b)
        String body = b.text.strip()
        Path source = Files.walk(Path.of('src/test/java')).withCloseable { s ->
            s.filter { it.toString().endsWith('.java') }.toList()
        }.find { Files.readString(it).strip() == body }
        assert source: "${b}: no file under src/test/java is exactly this block"
        String pkg = (body =~ /(?m)^package ([\w.]+);/)[0][1]
        String name = source.fileName.toString() - '.java'
        assert Files.walk(Path.of('src/test')).withCloseable { s -> s.filter { it != source && Files.isRegularFile(it) }.toList() }
                .any { Files.readString(it).contains(name) }: "${b}: ${source} is used by no test"
        Class<?> type = Class.forName("${pkg}.${name}")
        if (type.methods.any { it.name == 'main' }) {
            def bytes = new ByteArrayOutputStream()
            PrintStream saved = System.out
            System.setOut(new PrintStream(bytes, true, 'UTF-8'))
            try {
                type.getMethod('main', String[].class).invoke(null, [[] as String[]] as Object[])
            } finally {
                System.setOut(saved)
            }
            lastOutput[b.doc] = bytes.toString('UTF-8')
        }
    }

    /**
     * A text block is a sample or a diagram, not run; with `output` its lines appear, in order, in the
     * output of the block above, with `file: PATH` in that file. Whitespace runs count as one space;
     * a line `...` stands for any lines, and a line ending in `...` for any ending.
     */
    void sample(Block b) {
        allow(b, 'output', 'file')
        if (!b.has('output') && !b.has('file')) {
            return
        }
        String actual = actual(b)
        List<String> lines = actual.readLines()*.trim()*.replaceAll(/\s+/, ' ')
        int at = 0
        b.text.readLines()*.trim()*.replaceAll(/\s+/, ' ').findAll { it && it != '...' }.each { String want ->
            boolean prefix = want.endsWith('...')
            String w = prefix ? want[0..-4].trim() : want
            int i = lines.findIndexOf(at) { prefix ? it.startsWith(w) : it == w }
            assert i >= at: "${b}: the line '${want}' is not in ${b.has('file') ? b.one('file') : 'the output above'} (in order):\n${actual}"
            at = i + 1
        }
    }

    /** A json block parses; with `file: PATH` it is a part of that file: the same keys and values, arrays cut short. */
    void jsonSample(Block b) {
        allow(b, 'file')
        def sample = new JsonSlurper().parseText(b.text)
        if (b.has('file')) {
            assert within(sample, new JsonSlurper().parseText(actual(b))): "${b}: the sample is not a part of ${b.one('file')}:\n${actual(b)}"
        }
    }

    /**
     * A lua block is the Neovim configuration of docs/editors.md, which NeovimSpec runs in a real
     * Neovim with the server's command replaced by the test's own: it must hold that command once.
     */
    void neovimConfig(Block b) {
        allow(b)
        assert b.doc == DOCS.resolve('editors.md').toString(): "${b}: NeovimSpec runs the lua block of docs/editors.md only"
        assert b.text.count(dolphin.editor.NeovimSpec.DOCUMENTED_COMMAND) == 1:
                "${b}: the server's command must be written ${dolphin.editor.NeovimSpec.DOCUMENTED_COMMAND}, once: NeovimSpec replaces it"
    }

    /**
     * An elisp block is Emacs configuration: whole forms, their brackets balanced outside strings,
     * comments and character literals (?( is a character, not a bracket).
     */
    void emacsConfig(Block b) {
        allow(b)
        String text = b.text
        List<String> closers = []
        int forms = 0
        int i = 0
        while (i < text.length()) {
            char c = text.charAt(i)
            boolean tokenStart = i == 0 || Character.isWhitespace(text.charAt(i - 1)) || text.charAt(i - 1) == '(' as char
            if (c == ';' as char) {
                i = text.indexOf('\n', i)
            } else if (c == '"' as char) {
                i++
                while (i < text.length() && text.charAt(i) != '"' as char) {
                    i += text.charAt(i) == '\\' as char ? 2 : 1
                }
                assert i < text.length(): "${b}: a string that is never closed"
            } else if (c == '?' as char && tokenStart) {
                i += text.charAt(i + 1) == '\\' as char ? 2 : 1
            } else if (c == '(' as char || c == '[' as char) {
                forms += closers.isEmpty() ? 1 : 0
                closers << (c == '(' as char ? ')' : ']')
            } else if (c == ')' as char || c == ']' as char) {
                assert closers && closers.removeLast() == String.valueOf(c): "${b}: '${c}' at offset ${i} closes nothing it opened"
            } else {
                assert closers || Character.isWhitespace(c): "${b}: '${c}' at offset ${i} is outside any form"
            }
            i++
        }
        assert closers.isEmpty(): "${b}: ${closers.size()} bracket(s) never closed"
        assert forms > 0: "${b}: no form"
    }

    static boolean within(Object part, Object whole) {
        if (part instanceof Map) {
            return whole instanceof Map && part.every { k, v -> whole.containsKey(k) && within(v, whole[k]) }
        }
        if (part instanceof List) {
            return whole instanceof List && part.size() <= whole.size() && (0..<part.size()).every { within(part[it], whole[it]) }
        }
        part instanceof Number && whole instanceof Number ? part.toBigDecimal() == whole.toBigDecimal() : part == whole
    }

    String actual(Block b) {
        if (b.has('file')) {
            Path f = workDir(b).resolve(b.one('file'))
            assert Files.exists(f): "${b}: no file ${b.one('file')} written by the blocks above"
            return Files.readString(f)
        }
        assert lastOutput[b.doc] != null: "${b}: 'output' needs a block above that ran"
        lastOutput[b.doc]
    }

    static void allow(Block b, String... names) {
        b.directives.each { assert it[0] in names: "${b}: the directive '${it[0]}' does not apply to ${b.kind} blocks" }
    }
}
