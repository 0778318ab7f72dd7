package dolphin.editor

import dolphin.dsl.vocabulary.Param
import dolphin.dsl.vocabulary.Signature
import dolphin.dsl.vocabulary.WordEntry
import spock.lang.Specification

/** What completion inserts for a word with arguments: its first usage, a placeholder for each parameter it needs. */
class WordSnippetSpec extends Specification {

    static final Param LAT = new Param('lat', Number, 'degrees', null)
    static final Param LON = new Param('lon', Number, 'degrees', null)
    static final Param HAE = new Param('hae', Number, 'metres above mean sea level', null)

    static WordEntry word(String name, List<Signature> signatures) {
        new WordEntry(name, 'what it does', signatures, false)
    }

    static Signature form(Param... params) {
        new Signature(params as List, false, void)
    }

    static Param closure(String name) {
        new Param(name, Closure, '', null)
    }

    def "the parameters the first form needs, the optional ones left out"() {
        expect:
        WordSnippet.of(word('goPos', [form(LAT, LON, HAE), form(LAT, LON), form(new Param('position', Object, '', null))]), false) ==
                'goPos(${1:lat}, ${2:lon})'
    }

    def "a closure as a block, with its placeholder inside; a closure alone without parentheses"() {
        expect:
        WordSnippet.of(word('move', [form(new Param('position', Object, '', null), closure('offset'))]), false) ==
                'move(${1:position}, { ${2:offset} })'
        WordSnippet.of(word('pick', [form(closure('clauses'))]), false) == 'pick { ${1:clauses} }'
    }

    def "the second word of a two-word instruction in command syntax, as scripts write it"() {
        expect:
        WordSnippet.of(word('then', [form(new Param('task', Object, '', null))]), true) == 'then ${1:task}'
        WordSnippet.of(word('then', [form(closure('task'))]), true) == 'then { ${1:task} }'
    }

    def "a variable number of values: one placeholder, named without the dots"() {
        expect:
        WordSnippet.of(word('allOf', [new Signature([new Param('tasks', Object[], '', null)], true, void)]), false) ==
                'allOf(${1:tasks})'
    }

    def "nothing for a word that needs no argument, nor for a unit"() {
        expect:
        WordSnippet.of(word('returnHomeAndLand', [form()]), false) == null
        WordSnippet.of(word('altitude', [form(HAE), form()]), false) == null
        WordSnippet.of(new WordEntry('minutes', 'Minutes, as seconds', [], true), false) == null
    }
}
