package dolphin.cli

import dolphin.dsl.vocabulary.LanguageWords
import dolphin.dsl.vocabulary.Vocabulary
import dolphin.dsl.vocabulary.WordScope
import dolphin.editor.GdslFile
import spock.lang.Shared
import spock.lang.Specification

class WordsCommandSpec extends Specification {

    @Shared
    Vocabulary language = LanguageWords.vocabulary()

    Map words(String... args) {
        def out = new StringWriter()
        def err = new StringWriter()
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(['words', *args] as String[])
        [code: code, out: out.toString(), err: err.toString()]
    }

    /** The lines under each heading of a listing: heading, then its lines. */
    static Map<String, List<String>> sections(String listing) {
        listing.split('\n\n').collectEntries { String part ->
            List<String> lines = part.readLines()
            [lines[0], lines.drop(1)]
        }
    }

    static String heading(WordScope s) {
        s.kind() == WordScope.ScopeKind.UNITS ? 'Units, after a number, as in 10.minutes' : s.where().capitalize()
    }

    def "every scope under its heading, in the vocabulary's order: the top level first, the units last"() {
        when:
        def r = words()

        then:
        r.code == 0
        r.err.isEmpty()
        sections(r.out).keySet() as List == language.scopes().collect { heading(it) }
        sections(r.out).keySet().containsAll(["At the script's top level", 'Inside mission { }', 'Inside pick { }',
                                              'After waitFor or when', 'Inside fence { }'])
    }

    def "each word's usages, one a line, with its line beside the first"() {
        given:
        def listed = sections(words().out)
        def misplaced = language.scopes().collectMany { s ->
            List<String> lines = listed[heading(s)].collect { it.trim() }
            s.words().values().findAll { w ->
                int at = lines.findIndexOf { it.startsWith(w.usages()[0] + '  ') || it == w.usages()[0] }
                !(at >= 0 && (lines[at].endsWith('  ' + w.description()) || lines[at + 1] == w.description())
                        && w.usages().drop(1).every { u -> u in lines })
            }.collect { "${heading(s)}: ${it.name()}" }
        }

        expect:
        misplaced == []
    }

    def "the descriptions of a scope start in one column, a long usage putting its description on the next line"() {
        given:
        def mission = sections(words('mission').out)['Inside mission { }']
        def column = { String line, String description -> line.indexOf(description) }
        def goPos = mission.find { it.contains('goPos(lat, lon[, hae])') }
        def delay = mission.find { it.startsWith('  delay(seconds)') }
        int survey = mission.findIndexOf { it.trim() == 'surveyArea(base, length, width[, spacing][, direction])' }

        expect:
        column(goPos, 'A waypoint') == column(delay, 'Waits this many seconds')
        survey >= 0
        column(mission[survey + 1], 'A lawnmower survey') == column(delay, 'Waits this many seconds')
    }

    def "one scope, named by a word that opens it: #name"() {
        when:
        def r = words(name)

        then:
        r.code == 0
        sections(r.out).keySet() == [heading] as Set
        r.out.contains(word)

        where:
        name      | heading                                      | word
        'mission' | 'Inside mission { }'                         | 'goPos(lat, lon[, hae])'
        'fence'   | 'Inside fence { }'                           | 'polygon(vertices...)'
        'pick'    | 'Inside pick { }'                            | 'payload(names...)'
        'oneOf'   | 'Inside allOf { }, choose { } or oneOf { }'  | 'when { condition }'
        'waitFor' | 'After waitFor or when'                      | 'then(task)'
        'script'  | "At the script's top level"                  | 'pick { clauses }'
        'units'   | 'Units, after a number, as in 10.minutes'    | 'n.minutes'
    }

    def "an unknown scope: exit 2, the near names and every known one"() {
        when:
        def r = words('misson')

        then:
        r.code == 2
        r.out.isEmpty()
        r.err.contains("dolphin words: unknown scope 'misson'; did you mean 'mission'?")
        r.err.contains('Known scopes: script, ')
        ['mission', 'fence', 'pick', 'waitFor', 'onError', 'units'].every { r.err.contains(it) }
    }

    def "--gdsl prints the GDSL file; with a scope it is a usage error"() {
        expect:
        words('--gdsl').out == GdslFile.of(language)
        words('--gdsl').code == 0
        words('--gdsl', 'mission').code == 2
        words('--gdsl', 'mission').err.contains('--gdsl prints the whole file: give no scope')
    }
}
