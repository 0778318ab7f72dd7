package dolphin.dsl.vocabulary

import dolphin.dsl.Picker
import dolphin.mission.dsl.FenceBuilder
import dolphin.mission.dsl.MissionBuilder
import spock.lang.Shared
import spock.lang.Specification

/**
 * The docs' tables of words say what the runtime has: every word of a scope once, with the forms the
 * vocabulary reads from its methods (the docs may add defaults: {@code [, hae = 0]}), so a word
 * renamed, added or given a new form cannot leave the docs behind. Every scope has its table.
 */
class DocsWordsSpec extends Specification {

    static final String GUIDE = 'docs/guide.md'
    static final String EVERY_WORD = '## Every word'

    /** The scopes with tables of their own elsewhere: page, heading, the column of the words. */
    static final Map<Class<?>, List> OWN_TABLES = [
            (MissionBuilder): ['docs/mission-commands.md', '## The commands', 1],
            (FenceBuilder)  : ['docs/airspace.md', '## In scripts', 0],
            (Picker)        : [GUIDE, '### Vehicles: pick, release, queries', 0],
    ]

    @Shared
    Vocabulary language = LanguageWords.vocabulary()

    def "the table of mission commands lists every word of mission { } once, with its forms"() {
        expect:
        agree(problems(MissionBuilder))
    }

    def "the fence words in airspace.md: every word of fence { } once, and fence and rally as mission { } has them"() {
        expect:
        agree(problems(FenceBuilder, [language.scopeOf(MissionBuilder).get()]))
    }

    def "the clauses of pick { } in the guide: every clause once, with its forms"() {
        expect:
        agree(problems(Picker))
    }

    def "the guide's Every word: a table for every other scope, each word once with its forms and its line"() {
        given:
        def scopes = language.scopes().findAll { !OWN_TABLES.containsKey(it.type()) }

        expect:
        agree(scopes.collectMany { everyWordProblems(it) })
    }

    def "Every word has no section for a scope the language does not have"() {
        given:
        def headings = language.scopes().collect { heading(it) }
        def lines = new File(GUIDE).readLines()
        def sections = lines.drop(lines.indexOf(EVERY_WORD) + 1).takeWhile { !it.startsWith('## ') }
                .findAll { it.startsWith('### ') }.collect { it.substring(4) }

        expect:
        lines.contains(EVERY_WORD)
        sections.findAll { !(it in headings) } == []
        sections.size() == language.scopes().size() - OWN_TABLES.size()
    }

    def "the tables that name words among other things name words the language has: #heading"() {
        given:
        DocTable table = DocTable.under(doc, heading)
        def unknown = table.rows.collectMany { row ->
            row.code(0).findAll { it ==~ /^[a-z].*/ }.collect { (it =~ /^[A-Za-z]+/)[0] }
                    .findAll { !(it in language.names()) }.collect { "${row.where}: '${it}' is no word of the language" }
        }

        expect:
        table != null
        agree(unknown)

        where:
        doc                        | heading
        GUIDE                      | '### Tasks and execute'
        GUIDE                      | '### Messages, signals, input, pausing, halting'
        'docs/mission-commands.md' | '## Position words'
    }

    def "the checks see a wrong row: a renamed parameter, a missing form, a word the scope lacks, a word twice"() {
        given:
        def mission = language.scopeOf(MissionBuilder).get()
        def rows = [row(1, '`goPos(latitude, lon[, hae = 0])`, `goPos(position)`'), row(2, '`home(lat, lon[, hae = 0])`'),
                    row(3, '`fly(north)`'), row(4, '`delay(seconds)`'), row(5, '`delay(seconds)`')]

        when:
        def found = rowProblems(rows, 0, mission, [], false)

        then:
        found.any { it.startsWith('x.md:1: goPos: the row says goPos(latitude, lon[, hae]), goPos(position); the vocabulary says goPos(lat, lon[, hae]), goPos(position)') }
        found.any { it.startsWith('x.md:2: home: the row says home(lat, lon[, hae]); the vocabulary says home(lat, lon[, hae]), home(position)') }
        found.any { it.startsWith("x.md:3: 'fly' is no word inside mission { }") }
        found.any { it.startsWith('x.md:5: delay is listed again (first at line 4)') }
        found.any { it.startsWith('x.md: no row for takeOff: the vocabulary says takeOff(position[, pitch])') }
    }

    /** One line per problem, so that the failure reads as a list of rows to fix. */
    private static boolean agree(List<String> problems) {
        assert problems.isEmpty(), problems.join('\n')
        true
    }

    private static DocTable.Row row(int line, String words) {
        new DocTable.Row(doc: 'x.md', line: line, cells: [words, 'what it does'])
    }

    private List<String> problems(Class<?> type, List<WordScope> alsoFrom = []) {
        def (String doc, String heading, int column) = OWN_TABLES[type]
        DocTable table = DocTable.under(doc, heading)
        if (table == null) {
            return ["${doc}: no table under '${heading}' for the words ${language.scopeOf(type).get().where()}".toString()]
        }
        rowProblems(table.rows, column, language.scopeOf(type).get(), alsoFrom, false)
    }

    private List<String> everyWordProblems(WordScope scope) {
        String heading = '### ' + heading(scope)
        DocTable table = DocTable.under(GUIDE, heading, EVERY_WORD)
        if (table == null) {
            return ["${GUIDE}: no section '${heading}' under '${EVERY_WORD}' with a table of the words ${scope.where()}: "
                            + "| Word | What it does | with the rows\n" + scope.words().values().collect { tableRow(it) }.join('\n')]
        }
        rowProblems(table.rows, 0, scope, [], true)
    }

    /** The heading of a scope's section: "At the script's top level", "Inside pos { }", "Units". */
    static String heading(WordScope scope) {
        scope.kind() == WordScope.ScopeKind.UNITS ? 'Units' : scope.where().capitalize()
    }

    /** How Every word writes a word: its usages in code, then its line. */
    static String tableRow(WordEntry w) {
        "| ${w.usages().collect { '`' + it + '`' }.join(', ')} | ${w.description().replace('|', '\\|')} |"
    }

    /**
     * What is wrong with the rows of a scope's table: a row for no word of the scope (or of
     * {@code alsoFrom}, the scopes whose words the table may also show), a word twice, usages that
     * are not the vocabulary's, a word without a row; with {@code descriptions}, a line that is not
     * the word's.
     */
    private static List<String> rowProblems(List<DocTable.Row> rows, int column, WordScope scope, List<WordScope> alsoFrom,
                                            boolean descriptions) {
        List<String> found = []
        Map<String, Integer> seen = [:]
        for (DocTable.Row row : rows) {
            List<String> usages = row.code(column).collect { DocTable.withoutDefaults(it) }
            // a unit is written n.minutes
            String name = usages ? (usages[0] =~ /^(?:n\.)?([A-Za-z]+)/).with { it.find() ? it.group(1) : usages[0] } : row.cells[column]
            WordEntry word = ([scope] + alsoFrom).findResult { it.words()[name] }
            if (word == null) {
                found << "${row.where}: '${name}' is no word ${scope.where()}; its words: ${scope.words().keySet().join(', ')}".toString()
                continue
            }
            if (seen.containsKey(name)) {
                found << "${row.where}: ${name} is listed again (first at line ${seen[name]})".toString()
                continue
            }
            seen[name] = row.line
            if (usages.toSet() != word.usages().toSet() || usages.size() != word.usages().size()) {
                found << ("${row.where}: ${name}: the row says ${usages.join(', ')}; the vocabulary says ${word.usages().join(', ')}"
                        + " (keep the docs' defaults, as in [, hae = 0])").toString()
            }
            if (descriptions && row.cells[1] != word.description()) {
                found << "${row.where}: ${name}: the row's line is not the word's; write ${tableRow(word)}".toString()
            }
        }
        scope.words().values().findAll { !seen.containsKey(it.name()) }.each { w ->
            found << ("${rows ? rows[0].doc : 'the table'}: no row for ${w.name()}: the vocabulary says ${w.usages().join(', ')}: "
                    + w.description()).toString()
        }
        found
    }
}
