package dolphin.editor

import org.eclipse.lsp4j.CompletionItem
import org.eclipse.lsp4j.CompletionItemKind
import org.eclipse.lsp4j.CompletionList
import org.eclipse.lsp4j.InsertTextFormat
import org.eclipse.lsp4j.Position
import org.eclipse.lsp4j.Range
import spock.lang.AutoCleanup
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

/**
 * Completion through the protocol: the words valid at the cursor, the block's own first, in code that
 * need not compile; those that begin with the typed word first, then those that hold its letters in
 * order, then spelling guesses, each replacing the whole word under the cursor.
 */
@Timeout(60)
class CompletionSpec extends Specification {

    static final String URI = 'file:///work/complete.dolphin'
    static final List<String> MISSION_WORDS = ['goPos', 'takeOff', 'surveyArea', 'returnHomeAndLand', 'loiterTime', 'fence']
    static final List<String> PICK_WORDS = ['count', 'id', 'payload', 'region', 'timeout', 'type']
    static final List<String> FENCE_WORDS = ['circle', 'enable', 'exclusion', 'inclusion', 'polygon', 'returnPoint']

    static final List<String> MISSION_MOVE_WORDS = ['move', 'moveAndLoiterFromHome', 'moveAndLoiterPos', 'moveAndLoiterTime',
            'moveAndLoiterTimeFromHome', 'moveAndLoiterTurns', 'moveAndLoiterTurnsFromHome', 'moveFromHome']

    @Shared
    @AutoCleanup
    LspTestClient client = new LspTestClient()

    @Shared
    @AutoCleanup
    LspTestClient snippetClient = LspTestClient.takingSnippets()

    int version = 0

    /** The items for the '|' in the text, in the order a client shows them (by sortText). */
    List<CompletionItem> complete(String marked) {
        completionList(marked).items.sort { it.sortText }
    }

    /** The answer for the '|' in the text, as sent. */
    CompletionList completionList(String marked) {
        def (text, at) = LspTestClient.cursor(marked)
        if (version == 0) {
            client.open(URI, text)
        } else {
            client.change(URI, version + 1, text)
        }
        version++
        client.completionList(URI, at)
    }

    /** The labels of the items that begin with the typed word (sortText's first digit, CompletionMatch.PREFIX), in order. */
    List<String> beginning(String marked) {
        complete(marked).findAll { it.sortText.startsWith('0') }*.label
    }

    /** The items for the '|' in the text, by label, from a client that takes snippets. */
    Map<String, CompletionItem> completeWithSnippets(String marked) {
        def (text, at) = LspTestClient.cursor(marked)
        snippetClient.open(URI, text)
        try {
            snippetClient.complete(URI, at).collectEntries { [it.label, it] }
        } finally {
            snippetClient.closeDocument(URI)
        }
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
        def missionGroup = items.takeWhile { it.sortText.startsWith('001') }*.label

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
        def labels = beginning('''v1 = pick {
    type 'UAV'
    t|
}
''')

        then: 'the clauses that begin with t, then the script words that do'
        labels == ['timeout', 'type', 'takenOver', 'takeovers', 'task', 'telemetry']
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
        beginning('pause 2.mi|\n') == ['minutes']
        complete('pause 2.mi|\n')*.label.first() == 'minutes'
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
        beginning('m = mission {\n    name "a { b"\n    // }\n    go|\n}\n') == ['goPos']
        complete('message "at ${pos { l| }}"\n')*.label.take(2) == ['lat', 'lon']
    }

    def "an unclosed block in a script that does not parse: completion still knows where it is"() {
        expect:
        beginning('x = (1 +\nm = mission {\n    takeOff location(1, 2, 3)\n    ret|') ==
                ['returnHome', 'returnHomeAndLand', 'returnHomeAndLandOnRunway', 'returnHomeAndLandVertically', 'returnHomeAndLoiter']
    }

    def "mv|oe inside mission { }: move and the mission's other move words first, each replacing the whole word"() {
        when:
        def items = completionList('m = mission {\n    takeOff location(1, 2, 3)\n    mv|oe\n}\n').items

        then: 'in the order of their sortText, as sent'
        items == items.toSorted { it.sortText }
        items*.label.take(MISSION_MOVE_WORDS.size()) == MISSION_MOVE_WORDS

        and: "the script's move words after the mission's"
        items*.label.indexOf('moveDistance') > MISSION_MOVE_WORDS.size() - 1

        and: 'each replaces mvoe whole, with the word alone (this client takes no snippets), matched as its name'
        items.every { it.textEdit.getLeft().range == new Range(new Position(2, 4), new Position(2, 8)) }
        items[0].textEdit.getLeft().newText == 'move'
        items[0].filterText == 'move'
        items[0].insertTextFormat == null
    }

    def "those that begin with the typed word first, then those that hold its letters in order, then spelling guesses"() {
        when:
        def labels = complete('''hpos = 1
happens = 2
xHp = 3
hx = 4
ph = 5
hp|
''')*.label

        then:
        labels.indexOf('hpos') < labels.indexOf('happens')
        labels.indexOf('happens') < labels.indexOf('xHp')
        labels.indexOf('xHp') < labels.indexOf('hx')
        labels.last() == 'hx'
        !labels.contains('ph')
    }

    def "a spelling guess is matched as the word typed, so that an editor that filters by it keeps it; its list is marked incomplete"() {
        when:
        def list = completionList('m = mission {\n    tkaeOff|\n}\n')
        def takeOff = list.items.find { it.label == 'takeOff' }

        then:
        takeOff.sortText.startsWith('2')
        takeOff.filterText == 'tkaeOff'
        takeOff.textEdit.getLeft().range == new Range(new Position(1, 4), new Position(1, 11))
        list.incomplete
    }

    def "a list neither cut nor holding guesses is complete"() {
        when:
        def list = completionList('m = mission {\n    goP|\n}\n')

        then:
        list.items*.label.first() == 'goPos'
        !list.incomplete
    }

    def "a list longer than an answer holds is cut and marked incomplete; typing more finds the rest"() {
        given:
        String variables = (0..<300).collect { "v${it} = ${it}\n" }.join()

        when:
        def all = complete(variables + '|')
        def typed = completionList(variables + 'v29|')

        then:
        all.size() == Completions.MOST_ITEMS
        !all*.label.contains('v299')
        typed.items*.label.containsAll(['v29', 'v290', 'v299'])
        typed.items.size() < Completions.MOST_ITEMS
    }

    def "no word is offered twice: a word of the block and of the script alike comes once, as the block's"() {
        when:
        def moves = complete('m = mission {\n    mo|\n}\n').findAll { it.label == 'move' }

        then:
        moves.size() == 1
        moves[0].detail.startsWith('move(north, east')
    }

    def "an editor that takes snippets gets placeholders for the arguments a word needs"() {
        when:
        def inMission = completeWithSnippets('m = mission {\n    goP|\n}\n')
        def goPos = inMission.goPos

        then:
        goPos.textEdit.getLeft().newText == 'goPos(${1:lat}, ${2:lon})'
        goPos.insertTextFormat == InsertTextFormat.Snippet
        goPos.filterText == 'goPos'

        and: 'a word that needs none inserts itself alone'
        completeWithSnippets('m = mission {\n    returnHomeAndL|\n}\n').returnHomeAndLand.textEdit.getLeft().newText == 'returnHomeAndLand'

        and: 'a closure as a block, the second word of an instruction in command syntax'
        completeWithSnippets('v1 = pi|\n').pick.textEdit.getLeft().newText ==~ /pick \{ \$\{1:\w+} }/
        completeWithSnippets('execute v1: waitFor { battery(v1) >= 0.9 } th|\n').then.textEdit.getLeft().newText ==~ /then \$\{1:\w+}/
    }

    def "no placeholders where the arguments are written already, nor for a unit"() {
        expect:
        completeWithSnippets('m = mission {\n    goP| 41.1, -8.6\n}\n').goPos.textEdit.getLeft().newText == 'goPos'
        completeWithSnippets('m = mission {\n    goP|os(41.1, -8.6)\n}\n').goPos.textEdit.getLeft().newText == 'goPos'
        completeWithSnippets('pause 2.mi|\n').minutes.insertTextFormat == null
    }
}
