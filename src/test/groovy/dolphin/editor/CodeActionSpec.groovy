package dolphin.editor

import org.eclipse.lsp4j.CodeActionKind
import org.eclipse.lsp4j.Position
import org.eclipse.lsp4j.Range
import org.eclipse.lsp4j.TextEdit
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout

/**
 * Quick fixes: the corrections the check knows (each "did you mean", each trap of the Groovy
 * embedding) as code actions of the diagnostic they fix, over LSP4J's client, on a virtual clock.
 */
@Timeout(60)
class CodeActionSpec extends Specification {

    static final String URI = 'file:///work/survey.dolphin'

    @AutoCleanup
    LspTestClient client = new LspTestClient()

    static Range range(int line, int from, int toLine, int to) {
        new Range(new Position(line, from), new Position(toLine, to))
    }

    def "initialize says the server offers quick fixes"() {
        expect:
        client.initialized.capabilities.codeActionProvider.getRight().codeActionKinds == [CodeActionKind.QuickFix]
    }

    def "a 'did you mean' gets a quick fix per suggestion, for the diagnostic the client shows or for its range"() {
        given:
        client.open(URI, 'm = mission {\n    mvoe 50, 0\n    land()\n}\n')
        def d = client.diagnostics(URI, 1).diagnostics

        when:
        def shown = client.codeActions(URI, d[0].range, [d[0]])
        def inRange = client.codeActions(URI, range(1, 5, 1, 5), [])
        def both = client.codeActions(URI, range(1, 0, 2, 0), d)

        then:
        d*.message*.getLeft() == ["unknown command 'mvoe' in mission { }; did you mean 'move'?",
                                  "unknown command 'land' in mission { }; did you mean 'landOnRunway' or 'landingPoint' or 'landVertically'?"]
        shown.size() == 1
        with(shown[0]) {
            title == "Change 'mvoe' to 'move'"
            kind == CodeActionKind.QuickFix
            diagnostics == [d[0]]
            edit.changes == [(URI): [new TextEdit(range(1, 4, 1, 8), 'move')]]
            isPreferred
        }
        inRange == shown
        both*.title == ["Change 'mvoe' to 'move'", "Change 'land' to 'landOnRunway'", "Change 'land' to 'landingPoint'",
                         "Change 'land' to 'landVertically'"]
        !both[1].isPreferred
    }

    def "a trap's diagnostic gets the fix that writes what Groovy reads as meant: execute alone on its line"() {
        given:
        client.open(URI, 'v1 = pick { }\nexecute\n    v1: idle(1)\n')
        def d = client.diagnostics(URI, 1).diagnostics

        when:
        def actions = client.codeActions(URI, d[0].range, d)

        then:
        actions*.title == ["Join the next line to 'execute'"]
        actions[0].edit.changes[URI] == [new TextEdit(range(1, 7, 2, 4), ' ')]
    }

    def "no fix for a diagnostic without one, nor once the text has changed, nor for a document that is not open"() {
        given:
        client.open(URI, 'm = mission {\n    mvoe 50, 0\n}\nv = pick { count 1, 2 }\n')
        def d = client.diagnostics(URI, 1).diagnostics

        expect: 'a wrong number of arguments has no fix'
        client.codeActions(URI, d[1].range, [d[1]]) == []

        when:
        client.change(URI, 2, 'm = mission {\n    move 50, 0\n}\n')
        client.diagnostics(URI, 2)

        then:
        client.codeActions(URI, d[0].range, [d[0]]) == []
        client.codeActions('file:///nowhere.dolphin', d[0].range, [d[0]]) == []
    }
}
