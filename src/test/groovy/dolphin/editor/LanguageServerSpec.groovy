package dolphin.editor

import org.eclipse.lsp4j.CompletionItemKind
import org.eclipse.lsp4j.DiagnosticSeverity
import org.eclipse.lsp4j.Position
import org.eclipse.lsp4j.Range
import org.eclipse.lsp4j.TextDocumentSyncKind
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout

/**
 * The server in this process, driven by LSP4J's client over piped streams: its capabilities, the
 * diagnostics of open, change and close, and a client going away. Its clock is virtual, so the
 * quiet period before a check passes without real time.
 */
@Timeout(60)
class LanguageServerSpec extends Specification {

    static final String URI = 'file:///work/survey.dolphin'

    @AutoCleanup
    LspTestClient client = new LspTestClient()

    def "initialize says what the server offers: whole-text sync, completion after '.', hover, signature help, definition"() {
        when:
        def caps = client.initialized.capabilities

        then:
        caps.textDocumentSync.getLeft() == TextDocumentSyncKind.Full
        caps.completionProvider.triggerCharacters == ['.']
        caps.hoverProvider.getLeft()
        caps.signatureHelpProvider.triggerCharacters.containsAll(['(', ','])
        caps.definitionProvider.getLeft()
        client.initialized.serverInfo.name == 'dolphin'
    }

    def "a script with a mistake gets its diagnostic on open, an empty list once fixed, and an empty list when closed"() {
        given:
        String broken = 'm = mission {\n    goPos 1, 2\n    takeOff(\n}\n'

        when:
        client.open(URI, broken)
        def opened = client.diagnostics(URI, 1)

        then: 'the message of dolphin check, on the line it names, the closing brace underlined'
        opened.diagnostics.size() == 1
        with(opened.diagnostics[0]) {
            message.getLeft() == "unbalanced '}': expected ')' to close the '(' of line 3"
            range == new Range(new Position(3, 0), new Position(3, 1))
            severity == DiagnosticSeverity.Error
            source == 'dolphin'
        }

        when:
        client.change(URI, 2, 'm = mission {\n    goPos 1, 2\n}\n')

        then:
        client.diagnostics(URI, 2).diagnostics == []

        when:
        client.closeDocument(URI)

        then:
        client.diagnostics(URI, null).diagnostics == []
    }

    def "every finding of the check is published, as engine.check words it, each underlining the word it names"() {
        given:
        String text = """homePos = location(40.4, -7.3, 820)
m = mission {
    goPoz 40.1, -7.3, 900
    takeOff homePos, 1, 2, 3
}
fence { }
v1 = pick { type 'UAV'; timeout 30.secondz }
"""

        when:
        client.open(URI, text)
        def d = client.diagnostics(URI, 1).diagnostics

        then:
        d*.message*.getLeft() == ScriptChecker.withMavlinkWords().engine().check(text, 'survey.dolphin')*.message()
        d*.range == [new Range(new Position(2, 4), new Position(2, 9)),
                     new Range(new Position(3, 4), new Position(3, 11)),
                     new Range(new Position(5, 0), new Position(5, 5)),
                     new Range(new Position(6, 35), new Position(6, 42))]
    }

    def "an error with a column underlines the word there: 'execute' alone on its line"() {
        when:
        client.open(URI, 'm = mission { goPos 1, 2 }\nv1 = pick { type "UAV" }\nexecute\nv1: m\n')
        def d = client.diagnostics(URI, 1).diagnostics

        then:
        d.size() == 1
        d[0].message.getLeft().startsWith("'execute' stands alone on its line")
        d[0].range == new Range(new Position(2, 0), new Position(2, 7))
    }

    def "a script that does not parse still gets completion, and its syntax error"() {
        given:
        def (text, at) = LspTestClient.cursor('x = 1 +\nm = mission {\n    go|\n')

        when:
        client.open(URI, text)
        def d = client.diagnostics(URI, 1).diagnostics
        def items = client.complete(URI, at)

        then:
        d.size() == 1
        items.findAll { it.sortText.startsWith('0') }*.label == ['goPos']
    }

    def "bad input never ends the server: ten thousand nested brackets, binary noise, a script too large to check as you type"() {
        given:
        String deep = 'x = ' + '(' * 10_000 + '1' + ')' * 10_000 + '\n'
        String noise = (0..<4096).collect { (char) ((it * 7919) % 0xD7FF) }.join()
        String huge = 'x = 1\n' * 170_000

        when:
        client.open('file:///work/deep.dolphin', deep)
        client.open('file:///work/noise.dolphin', noise)
        client.open('file:///work/huge.dolphin', huge)
        def deepResult = client.diagnostics('file:///work/deep.dolphin', 1)
        def noiseResult = client.diagnostics('file:///work/noise.dolphin', 1)
        def hugeResult = client.diagnostics('file:///work/huge.dolphin', 1)

        then:
        deepResult.diagnostics == []
        !noiseResult.diagnostics.isEmpty()
        hugeResult.diagnostics*.message*.getLeft() == ["not checked: the script has ${huge.length()} characters, more than the "
                + "${ScriptChecker.MAX_CHARACTERS} the editor checks as you type; run dolphin check on it".toString()]

        and: 'the server still answers, on the huge script too'
        client.complete('file:///work/huge.dolphin', new Position(170_000, 0))*.label.containsAll(['mission', 'x'])
        client.hover('file:///work/deep.dolphin', new Position(0, 0)).contents.getRight().value.contains('Variable assigned at line 1')
    }

    def "a client that closes the server's input ends it with exit code 0"() {
        when:
        client.open(URI, 'message "hello"\n')
        client.diagnostics(URI, 1)

        then:
        client.disconnect() == 0
    }

    def "exit without shutdown ends the server with exit code 1"() {
        when:
        client.remote.exit()

        then:
        client.served.get(LspTestClient.DEADLINE_SECONDS, java.util.concurrent.TimeUnit.SECONDS) == 1
    }

    def "shutdown then exit ends the server with exit code 0"() {
        when:
        client.remote.shutdown().get()
        client.remote.exit()

        then:
        client.served.get(LspTestClient.DEADLINE_SECONDS, java.util.concurrent.TimeUnit.SECONDS) == 0
    }

    def "requests about a document that is not open get empty answers, not errors"() {
        expect:
        client.complete('file:///nowhere.dolphin', new Position(0, 0)) == []
        client.hover('file:///nowhere.dolphin', new Position(0, 0)) == null
        client.definition('file:///nowhere.dolphin', new Position(0, 0)) == []
    }

    def "completion items carry their usage as detail and their description as documentation"() {
        given:
        def (text, at) = LspTestClient.cursor('m = mission {\n    goP|\n}\n')
        client.open(URI, text)

        when:
        def item = client.complete(URI, at).find { it.label == 'goPos' }

        then:
        item.kind == CompletionItemKind.Function
        item.detail == 'goPos(lat, lon[, hae]) or goPos(position)'
        item.documentation.getRight().value == 'A waypoint at a position (degrees, metres above mean sea level)'
    }
}
