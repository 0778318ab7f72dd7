package dolphin.editor

import dolphin.dsl.ScriptError
import org.eclipse.lsp4j.Position
import org.eclipse.lsp4j.Range
import spock.lang.Specification

/** Where an error's line and column put its underline. */
class ErrorRangeSpec extends Specification {

    static final String TEXT = 'm = mission {\n    goPos 1, 2\n    takeOff(\n}\n'

    static Range range(int sl, int sc, int el, int ec) {
        new Range(new Position(sl, sc), new Position(el, ec))
    }

    def "line #line column #column is underlined at #expected"() {
        expect:
        ErrorRange.of(new ScriptError('f', line, column, 'm'), TEXT, new LineMap(TEXT)) == expected

        where:
        line | column || expected
        2    | 5      || range(1, 4, 1, 9)     // the word goPos
        2    | 7      || range(1, 4, 1, 9)     // inside it
        3    | 12     || range(2, 11, 2, 12)   // the '(' after takeOff
        4    | 1      || range(3, 0, 3, 1)     // the '}'
        2    | 0      || range(1, 0, 1, 14)    // no column: the whole line
        0    | 0      || range(0, 0, 0, 13)    // no line: the first line
        2    | 99     || range(1, 14, 1, 14)   // past the line's end: its end
        9    | 1      || range(4, 0, 4, 0)     // past the script's end: the last line
        2    | 1      || range(1, 0, 1, 14)    // on the indent: the rest of the line
    }

    def "a text with CRLF line ends: the '\\r' is no part of the line"() {
        given:
        String crlf = 'a = 1\r\nexecute\r\n'

        expect:
        ErrorRange.of(new ScriptError('f', 2, 0, 'm'), crlf, new LineMap(crlf)) == range(1, 0, 1, 7)
    }
}
