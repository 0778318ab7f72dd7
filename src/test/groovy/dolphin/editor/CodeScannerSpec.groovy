package dolphin.editor

import spock.lang.Specification

/** The lexical reading of the text before the cursor: blocks, strings, comments, the word being typed. */
class CodeScannerSpec extends Specification {

    static CursorContext scan(String marked) {
        CodeScanner.scan(marked.replace('|', ''), marked.indexOf('|'))
    }

    def "the words before each open brace, outermost first"() {
        expect:
        scan(text).blockOpeners() == openers

        where:
        text                                                    || openers
        '|'                                                     || []
        'm = mission { |'                                       || ['mission']
        'm = mission { fence { | } }'                           || ['mission', 'fence']
        'm = mission { fence { } |'                             || ['mission']
        'goPos move(p, { north 1; | })'                         || ['move']
        'def f(a) { |'                                          || ['f']
        'if (x) { mission { |'                                  || ['if', 'mission']
        'x = [1, { |'                                           || []
        'a = (b / { |'                                          || []
        'mission { name "}" ; /* } */ // }\n |'                 || ['mission']
        "mission { name '''\n}\n''' |"                          || ['mission']
        'mission { message "a ${pos { |'                        || ['mission', 'pos']
        'mission { message "a ${x}" ; pick { |'                 || ['mission', 'pick']
        'mission { name "unclosed\n pick { |'                   || ['mission', 'pick']
        'mission { } } } pick { |'                              || ['pick']
        'mission { goPos(1, 2 } pick { |'                       || ['pick']
    }

    def "code, string or comment at the cursor"() {
        expect:
        scan(text).inCode() == code

        where:
        text                      || code
        'x = 1|'                  || true
        'x = "a|'                 || false
        'x = "a" |'               || true
        'x = "${a|}"'             || true
        "x = '''\n|"              || false
        '// a|'                   || false
        '// a\n|'                 || true
        '/* a |'                  || false
        '/* a */ |'               || true
        'x = "a\\"|'              || false
        'x = 10 / 2 |'            || true
    }

    def "the word being typed, and what comes before it"() {
        when:
        def c = scan(text)

        then:
        c.prefix() == prefix
        c.afterDot() == dot
        c.afterNumberDot() == number

        where:
        text              || prefix    | dot   | number
        'goP|'            || 'goP'     | false | false
        'goPos |'         || ''        | false | false
        '10.|'            || ''        | true  | true
        '10.mi|'          || 'mi'      | true  | true
        '0.5.k|'          || 'k'       | true  | true
        'v1.i|'           || 'i'       | true  | false
        'x.|'             || ''        | true  | false
        '1e3.se|'         || 'se'      | true  | true
        '10 .mi|'         || 'mi'      | true  | false
    }

    def "the statement's tokens: a line end inside brackets or after an operator or a comma goes on with it"() {
        expect:
        scan(text).beforePrefix()*.text == tokens

        where:
        text                                 || tokens
        'goPos 1, 2|'                        || ['goPos', '1', ',', '2']
        'goPos 1,\n  2, |'                   || ['goPos', '1', ',', '2', ',']
        'a = 1\nb |'                         || ['b']
        'a = 1; b |'                         || ['b']
        'x = waitFor { c } |'                || ['x', '=', 'waitFor', 'waitFor']
        'execute v1: goPos(1, 2) |'          || ['execute', 'v1', ':', 'goPos', 'goPos']
        'a >>\n b |'                         || ['a', '>>', 'b']
    }

    def "a huge text is read in one pass without recursion: ten thousand open braces"() {
        when:
        def c = CodeScanner.scan('mission { ' * 10_000 + 'go', 10 * 10_000 + 2)

        then:
        c.blockOpeners().size() == 10_000
        c.prefix() == 'go'
    }
}
