package dolphin.editor

import org.eclipse.lsp4j.Position
import org.eclipse.lsp4j.Range
import spock.lang.AutoCleanup
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

/** Hover, signature help and go to definition through the protocol. */
@Timeout(60)
class HoverSignatureDefinitionSpec extends Specification {

    static final String URI = 'file:///work/survey.dolphin'
    static final String SCRIPT = '''homePos = location(40.444233, -7.375234, 820)
def height = 920
surveyNorth = mission {
    home homePos
    takeOff location(40.444233, -7.375234, height)
    goPos 40.45, -7.37, 920
    move 100, 50
}
p = move(homePos, { north 10 })
v1 = pick { timeout 30.seconds }
execute v1: surveyNorth
// goPos in a comment, "goPos" in a string
message "goPos"
'''

    @Shared
    @AutoCleanup
    LspTestClient client = new LspTestClient()

    int version = 0

    def setup() {
        client.open(URI, SCRIPT)
    }

    def cleanup() {
        client.closeDocument(URI)
    }

    /** The position of the n-th occurrence (from 1) of the text in the script, plus a few characters. */
    static Position at(String text, String what, int occurrence = 1, int plus = 1) {
        int i = -1
        occurrence.times { i = text.indexOf(what, i + 1) }
        assert i >= 0
        String before = text.substring(0, i + plus)
        new Position(before.count('\n'), before.length() - before.lastIndexOf('\n') - 1)
    }

    def "hover on a mission command: its usages, what it does, the units of its numbers and where it is written"() {
        when:
        def hover = client.hover(URI, at(SCRIPT, 'goPos'))
        String md = hover.contents.getRight().value

        then:
        md.contains('goPos(lat, lon[, hae])')
        md.contains('goPos(position)')
        md.contains('A waypoint at a position')
        md.contains('Units: lat, lon: degrees; hae: metres above mean sea level')
        md.contains('Written inside mission { }')
        hover.range == new Range(new Position(5, 4), new Position(5, 9))
    }

    def "hover is scope-aware: move inside a mission is the mission command, outside it the position word"() {
        when:
        String inMission = client.hover(URI, at(SCRIPT, 'move', 1)).contents.getRight().value
        String atTop = client.hover(URI, at(SCRIPT, 'move', 2)).contents.getRight().value

        then:
        inMission.contains('move(north, east[, up])')
        inMission.contains('Units: north, east, up: metres')
        atTop.contains('move(position, offset)')
        !atTop.contains('move(north, east')
    }

    def "hover on a unit after a number, and on a variable: where it is assigned"() {
        when:
        String unit = client.hover(URI, at(SCRIPT, 'seconds')).contents.getRight().value
        String variable = client.hover(URI, at(SCRIPT, 'surveyNorth', 2)).contents.getRight().value

        then:
        unit.contains('n.seconds')
        unit.contains('Seconds')
        variable.contains('surveyNorth = mission {')
        variable.contains('Variable assigned at line 3')
    }

    def "hover on no word, in a comment or in a string is empty"() {
        expect:
        client.hover(URI, new Position(0, 8)) == null
        client.hover(URI, at(SCRIPT, 'goPos', 2)) == null
        client.hover(URI, at(SCRIPT, 'goPos', 3)) == null
        client.hover(URI, at(SCRIPT, 'goPos', 4)) == null
    }

    def "signature help inside word(: the forms, the argument the cursor is on"() {
        when:
        client.change(URI, 2, SCRIPT + 'x = location(40.1, ')
        def help = client.signatureHelp(URI, new Position(SCRIPT.count('\n'), 'x = location(40.1, '.length()))

        then:
        help.signatures*.label == ['location(lat, lon[, height])']
        help.activeParameter == 1
        with(help.signatures[0]) {
            parameters.size() == 3
            parameters[1].label.getRight().first == 'location(lat, '.length()
            parameters[1].label.getRight().second == 'location(lat, lon'.length()
            parameters[1].documentation.getLeft() == 'lon: degrees'
        }
    }

    def "signature help in command syntax: goPos 41.1, -8.6, | is on hae"() {
        when:
        String text = 'm = mission {\n    goPos 41.1, -8.6, \n}\n'
        client.change(URI, 2, text)
        def help = client.signatureHelp(URI, new Position(1, '    goPos 41.1, -8.6, '.length()))

        then:
        help.signatures*.label == ['goPos(lat, lon[, hae])', 'goPos(position)']
        help.activeSignature == 0
        help.activeParameter == 2
    }

    def "signature help through a grouping parenthesis and a list: the call around them"() {
        when:
        client.change(URI, 2, 'm = mission {\n    surveyArea location(1, 2, 3), 3000, (10 + \n}\n')
        def survey = client.signatureHelp(URI, new Position(1, '    surveyArea location(1, 2, 3), 3000, (10 + '.length()))
        client.change(URI, 3, 'm = mission {\n    fence { inclusion polygon(location(1, 2), [')
        def polygon = client.signatureHelp(URI, new Position(1, '    fence { inclusion polygon(location(1, 2), ['.length()))

        then: 'the third argument of surveyArea, in its form with a base'
        survey.signatures*.label == ['surveyArea(base, length, width[, spacing][, direction])', 'surveyArea(length, width[, spacing][, direction])']
        survey.activeParameter == 2
        survey.activeSignature == 0
        polygon.signatures*.label == ['polygon(vertices...)']
        polygon.activeParameter == 1
        polygon.signatures[0].activeParameter == 0
    }

    def "signature help for the second word of a two-word instruction, and none after a finished word being typed"() {
        when:
        client.change(URI, 2, 'execute v1: waitFor { battery(v1) > 0.9 } then ')
        def then = client.signatureHelp(URI, new Position(0, 'execute v1: waitFor { battery(v1) > 0.9 } then '.length()))
        client.change(URI, 3, 'goPo')
        def typing = client.signatureHelp(URI, new Position(0, 4))

        then:
        then.signatures*.label == ['then(task)']
        typing == null
    }

    def "go to definition of a variable: the line where it is first assigned; a def variable too"() {
        when:
        def survey = client.definition(URI, at(SCRIPT, 'surveyNorth', 2))
        def height = client.definition(URI, at(SCRIPT, 'height', 2))

        then:
        survey.size() == 1
        survey[0].uri == URI
        survey[0].range == new Range(new Position(2, 0), new Position(2, 11))
        height[0].range == new Range(new Position(1, 4), new Position(1, 10))
    }

    def "go to definition in a script that does not parse: found in its text"() {
        when:
        String broken = SCRIPT + 'x = (1 +\n'
        client.change(URI, 2, broken)
        def survey = client.definition(URI, at(broken, 'surveyNorth', 2))

        then:
        survey[0].range == new Range(new Position(2, 0), new Position(2, 11))
    }

    def "no definition for a word of the language, nor for a name in a comment"() {
        when:
        String commented = SCRIPT + '// surveyNorth\n'
        client.change(URI, 2, commented)

        then:
        client.definition(URI, at(commented, 'goPos')) == []
        client.definition(URI, at(commented, 'surveyNorth', 2)) != []
        client.definition(URI, at(commented, 'surveyNorth', 3)) == []
    }
}
