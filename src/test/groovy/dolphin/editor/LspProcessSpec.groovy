package dolphin.editor

import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout

/** The server as its own process: the protocol alone on standard output, and how it ends. */
@Timeout(120)
class LspProcessSpec extends Specification {

    static final String URI = 'file:///work/broken.dolphin'

    @AutoCleanup
    LspProcess server = new LspProcess()

    def "shutdown then exit: exit code 0, and standard output held nothing but the protocol's messages"() {
        when:
        server.initialize()
        Map published = server.openChecked(URI, 'm = mission {\n    takeOff(\n}\n')
        int shutdown = server.request('shutdown', null)
        server.next { it.id == shutdown }
        server.notify('exit', null)

        then:
        published.params.diagnostics*.message == ["unbalanced '}': expected ')' to close the '(' of line 2"]
        published.params.diagnostics[0].range.start == [line: 2, character: 0]
        server.exitCode() == 0

        and: 'every byte left on its output is a whole message'
        List<Map> rest = []
        for (Map m = server.read(); m != null; m = server.read()) {
            rest << m
        }
        rest.every { it.jsonrpc == '2.0' }
    }

    def "a plain JSON-RPC client asks for the code actions of a diagnostic and gets the quick fix that replaces 'mvoe' with 'move'"() {
        when:
        server.initialize()
        Map published = server.openChecked(URI, 'm = mission {\n    mvoe 50, 0\n}\n')
        Map diagnostic = published.params.diagnostics[0]
        int asked = server.request('textDocument/codeAction', [textDocument: [uri: URI], range: diagnostic.range,
                                                               context: [diagnostics: [diagnostic]]])
        List<Map> actions = server.next { it.id == asked }.result

        then:
        diagnostic.message == "unknown command 'mvoe' in mission { }; did you mean 'move'?"
        actions.size() == 1
        actions[0].title == "Change 'mvoe' to 'move'"
        actions[0].kind == 'quickfix'
        actions[0].isPreferred
        actions[0].diagnostics == [diagnostic]
        actions[0].edit.changes == [(URI): [[range: [start: [line: 1, character: 4], end: [line: 1, character: 8]], newText: 'move']]]
    }

    def "a message that is not JSON, or a request for a method the server does not know, gets an error; the server goes on"() {
        when:
        server.initialize()
        server.sendRaw('{"jsonrpc": "2.0", "id": 99, "method": ')
        int unknown = server.request('textDocument/frobnicate', [:])
        Map unknownAnswer = server.next { it.id == unknown }
        int shutdown = server.request('shutdown', null)
        server.next { it.id == shutdown }
        server.notify('exit', null)

        then:
        unknownAnswer.error.code == -32601
        server.exitCode() == 0
    }

    def "exit without shutdown: exit code 1, as the protocol says"() {
        when:
        server.initialize()
        server.notify('exit', null)

        then:
        server.exitCode() == 1
    }

    def "a client that goes away (the server's input closed) ends the server cleanly: exit code 0"() {
        when:
        server.initialize()
        server.openChecked(URI, 'message "hi"\n')
        server.closeInput()

        then:
        server.exitCode() == 0
    }

    def "a client that goes away before it even initializes: exit code 0"() {
        when:
        server.closeInput()

        then:
        server.exitCode() == 0
    }

    def "a plain JSON-RPC client asking at mv|oe inside mission { } gets move and the other move words first, each replacing mvoe whole"() {
        when:
        server.initialize()
        List<Map> items = completeInMvoe()

        then:
        items*.label.take(CompletionSpec.MISSION_MOVE_WORDS.size()) == CompletionSpec.MISSION_MOVE_WORDS
        items == items.toSorted { it.sortText }
        items[0].textEdit == [range: [start: [line: 1, character: 4], end: [line: 1, character: 8]], newText: 'move']
        items[0].filterText == 'move'

        and: 'no snippet for a client that did not say it takes them'
        items.every { it.insertTextFormat == null }
    }

    def "a client that takes snippets gets move with placeholders for the arguments it needs"() {
        when:
        server.initialize([textDocument: [completion: [completionItem: [snippetSupport: true]]]])
        Map move = completeInMvoe()[0]

        then:
        move.label == 'move'
        move.textEdit.newText == 'move(${1:north}, ${2:east})'
        move.insertTextFormat == 2
    }

    private List<Map> completeInMvoe() {
        server.open(URI, 'm = mission {\n    mvoe\n}\n')
        int id = server.request('textDocument/completion', [textDocument: [uri: URI], position: [line: 1, character: 6]])
        server.next { it.id == id }.result.items as List<Map>
    }
}
