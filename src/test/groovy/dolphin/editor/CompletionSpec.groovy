package dolphin.editor

import org.eclipse.lsp4j.CompletionItem
import org.eclipse.lsp4j.CompletionItemKind
import spock.lang.AutoCleanup
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

/** Completion through the protocol: the words valid at the cursor, the block's own first, in code that need not compile. */
@Timeout(60)
class CompletionSpec extends Specification {

    static final String URI = 'file:///work/complete.dolphin'
    static final List<String> MISSION_WORDS = ['goPos', 'takeOff', 'surveyArea', 'returnHomeAndLand', 'loiterTime', 'fence']
    static final List<String> PICK_WORDS = ['count', 'id', 'payload', 'region', 'timeout', 'type']
    static final List<String> FENCE_WORDS = ['circle', 'enable', 'exclusion', 'inclusion', 'polygon', 'returnPoint']

    @Shared
    @AutoCleanup
    LspTestClient client = new LspTestClient()

    int version = 0

    /** The items for the '|' in the text, in the order a client shows them (by sortText). */
    List<CompletionItem> complete(String marked) {
        def (text, at) = LspTestClient.cursor(marked)
        if (version == 0) {
            client.open(URI, text)
        } else {
            client.change(URI, version + 1, text)
        }
        version++
        client.complete(URI, at).sort { it.sortText }
    }

    def cleanup() {
        if (version > 0) {
            client.closeDocument(URI)
        }
    }

    def "at the top level: the script's words and variables, no mission command"() {
        when:
        def labels = complete('''homePos = location(40.44, -7.37, 820)
def cutAt(v) { v }
|''')*.label

        then:
        labels.containsAll(['mission', 'pick', 'waitFor', 'execute', 'release', 'fenceBreached', 'homePos', 'cutAt'])
        !labels.contains('goPos')
        labels.indexOf('execute') < labels.indexOf('homePos')
    }

    def "inside mission { }: the mission commands first, then the script's words, then the variables"() {
        when:
        def items = complete('''homePos = location(40.44, -7.37, 820)
surveyNorth = mission {
    home homePos
    |
}
''')
        def labels = items*.label
        def missionGroup = items.takeWhile { it.sortText.startsWith('01') }*.label

        then:
        missionGroup.containsAll(MISSION_WORDS)
        !missionGroup.contains('pick')
        labels.indexOf('pick') > labels.indexOf('takeOff')
        labels.indexOf('homePos') > labels.indexOf('pick')
        items.find { it.label == 'homePos' }.kind == CompletionItemKind.Variable
        items.find { it.label == 'homePos' }.detail == 'assigned at line 1'
    }

    def "inside pick { }: the pick clauses first"() {
        when:
        def items = complete('''v1 = pick {
    type 'UAV'
    t|
}
''')

        then: 'the clauses that begin with t, then the script words that do'
        items*.label == ['timeout', 'type', 'takenOver', 'takeovers', 'task', 'telemetry']
    }

    def "inside pick { } with nothing typed: the six clauses, then the script's words"() {
        when:
        def labels = complete('v1 = pick { | }\n')*.label

        then:
        labels.take(6) == PICK_WORDS
        labels.contains('mission')
    }

    def "inside fence { } inside a mission: the fence words, then the mission's, then the script's"() {
        when:
        def labels = complete('''m = mission {
    takeOff location(1, 2, 3)
    fence {
        |
    }
}
''')*.label

        then:
        labels.take(6) == FENCE_WORDS
        labels.indexOf('goPos') > 5
        labels.indexOf('pick') > labels.indexOf('goPos')
    }

    def "after a number and a dot: the units, and only those that begin with what is typed"() {
        expect:
        complete('v1 = pick { timeout 30.| }\n').every { it.kind == CompletionItemKind.Unit }
        complete('v1 = pick { timeout 30.| }\n')*.label.containsAll(['seconds', 'minutes', 'hours', 'km', 'percent'])
        complete('pause 2.mi|\n')*.label == ['minutes']
    }

    def "after the first half of a two-word instruction: its second word"() {
        expect:
        complete('execute v1: waitFor { battery(v1) >= 0.9 } |')*.label == ['then']
        complete('execute v1: waitFor { battery(v1) >= 0.9 } th|')*.label == ['then']
        complete('execute v1: until { battery(v1) < 0.3 } |')*.label == ['run']
        complete('execute v1: during 30 |')*.label == ['run']
        complete('watch survey |')*.label == ['onError']
    }

    def "after the second word, the script's words again"() {
        when:
        def labels = complete('execute v1: waitFor { battery(v1) >= 0.9 } then |')*.label

        then:
        labels.containsAll(['mission', 'action', 'idle'])
        !labels.contains('then')
    }

    def "inside allOf { }: when, and after when { c } its then"() {
        expect:
        complete('allOf {\n    w|\n}\n')*.label.first() == 'when'
        complete('allOf {\n    when { battery(v1) > 0.5 } |\n}\n')*.label == ['then']
    }

    def "inside a move offset in a mission: north, east, down first"() {
        expect:
        complete('m = mission {\n    goPos move(location(1, 2, 3), { | })\n}\n')*.label.take(3) == ['down', 'east', 'north']
    }

    def "inside onError { }: ignore and propagate"() {
        expect:
        complete('watch t onError { | }\n')*.label.take(2) == ['ignore', 'propagate']
    }

    def "in a string, in a comment and after another object's dot: nothing"() {
        expect:
        complete('message "go|"\n') == []
        complete('// go|\n') == []
        complete('/* mission {\n go| */\n') == []
        complete('x = v1.|\n') == []
    }

    def "braces in strings and comments do not open blocks; code in \${ } is code"() {
        expect:
        complete('m = mission {\n    name "a { b"\n    // }\n    go|\n}\n')*.label == ['goPos']
        complete('message "at ${pos { l| }}"\n')*.label.take(2) == ['lat', 'lon']
    }

    def "an unclosed block in a script that does not parse: completion still knows where it is"() {
        expect:
        complete('x = (1 +\nm = mission {\n    takeOff location(1, 2, 3)\n    ret|')*.label ==
                ['returnHome', 'returnHomeAndLand', 'returnHomeAndLoiter']
    }
}
