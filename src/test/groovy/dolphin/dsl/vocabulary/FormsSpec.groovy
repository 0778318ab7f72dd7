package dolphin.dsl.vocabulary

import spock.lang.Specification

class FormsSpec extends Specification {

    static final Map<String, WordEntry> SAMPLE = Vocabulary.wordsOf(SampleWords)

    def "the methods Groovy makes for default arguments read as one form with optional parameters"() {
        expect:
        SAMPLE.goPos.forms() == ['(lat, lon[, hae])', '(position)']
        SAMPLE.goPos.usages() == ['goPos(lat, lon[, hae])', 'goPos(position)']
        SAMPLE.goPos.formsText() == '(lat, lon[, hae]) or (position)'
    }

    def "optionals left out from the end nest; optionals left out one at a time stand alone"() {
        expect:
        SAMPLE.loiterTurns.forms() == ['(lat, lon, hae[, turns[, radius]])']
        SAMPLE.surveyArea.forms() == ['(length, width[, spacing][, direction])']
    }

    def "varargs end in ..., a closure shows as its block and a closure alone reads as a block"() {
        expect:
        SAMPLE.rally.forms() == ['(points...)']
        SAMPLE.around.forms() == ['(position, { offset })']
        SAMPLE.around.usages() == ['around(position, { offset })']
        SAMPLE.block.forms() == ['({ commands })']
        SAMPLE.block.usages() == ['block { commands }']
        SAMPLE.stop.usages() == ['stop()']
    }

    def "forms whose first parameters differ are not merged"() {
        given:
        def at = { String name, Class type -> new Param(name, type, '', null) }
        def s1 = new Signature([at('lat', Number), at('lon', Number)], false, void)
        def s2 = new Signature([at('lon', Number)], false, void)
        def s3 = new Signature([at('lat', Number)], false, void)

        expect:
        Forms.of([s1, s2]) == ['(lat, lon)', '(lon)']
        Forms.of([s1, s3]) == ['(lat[, lon])']
        Forms.of([]) == []
    }

    def "a varargs form does not merge with a form without them"() {
        given:
        def points = new Param('points', Object[], '', null)
        def varargs = new Signature([points], true, void)
        def array = new Signature([], false, void)

        expect:
        Forms.of([varargs, array]) == ['(points...)', '()']
    }

    def "takes: how many arguments a form accepts, varargs any number from the fixed ones"() {
        expect:
        SAMPLE.goPos.takes(1)
        SAMPLE.goPos.takes(2)
        SAMPLE.goPos.takes(3)
        !SAMPLE.goPos.takes(4)
        SAMPLE.rally.takes(0)
        SAMPLE.rally.takes(7)
    }

    def "only methods marked @Word are words, and each keeps its one line"() {
        expect:
        !SAMPLE.containsKey('helper')
        SAMPLE.keySet() == ['around', 'block', 'goPos', 'loiterTurns', 'rally', 'stop', 'surveyArea', 'wait'] as Set
        SAMPLE.surveyArea.description() == 'Independent optionals'
    }
}
