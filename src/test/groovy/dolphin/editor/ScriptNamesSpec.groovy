package dolphin.editor

import spock.lang.Specification

/** The names a script assigns, from its syntax tree and, when it does not parse, from its tokens. */
class ScriptNamesSpec extends Specification {

    static final String SCRIPT = '''homePos = location(1, 2, 3)
def height = 920
def cutAt(v) { action { message "cut ${v}" } }
def (a, b) = [1, 2]
for (v in [1, 2]) { later = v }
x == 3
p.q = 4
// commented = 5
s = "quoted = 6"
homePos = location(4, 5, 6)
'''

    def "the syntax tree and the tokens agree on assignments, def variables and methods, each at its first place"() {
        when:
        def parsed = AstNames.of(SCRIPT)
        def typed = ScriptNames.of(SCRIPT)

        then:
        ['homePos', 'height', 'cutAt', 'later', 's'].every { parsed[it] == typed[it] }
        parsed.homePos.offset() == 0
        parsed.height.offset() == SCRIPT.indexOf('height')
        parsed.cutAt.method()
        !parsed.height.method()
        !parsed.containsKey('x') && !typed.containsKey('x')
        !parsed.containsKey('q') && !typed.containsKey('q')
        !parsed.containsKey('commented') && !typed.containsKey('commented')
        !parsed.containsKey('quoted') && !typed.containsKey('quoted')
    }

    def "only the syntax tree knows multiple assignment and loop variables"() {
        when:
        def parsed = AstNames.of(SCRIPT)

        then:
        parsed.a.offset() == SCRIPT.indexOf('(a, b)') + 1
        parsed.b.offset() == SCRIPT.indexOf('(a, b)') + 4
        parsed.v.offset() == SCRIPT.indexOf('v in')
    }

    def "a script that does not parse: the syntax tree throws, the tokens still give the names"() {
        given:
        String broken = SCRIPT + 'y = (1 +\n'

        when:
        AstNames.of(broken)

        then:
        thrown(RuntimeException)
        ScriptNames.of(broken).keySet().containsAll(['homePos', 'height', 'cutAt', 'y'])
        new OpenDocument('file:///x', 1, broken).definitions().containsKey('y')
    }
}
