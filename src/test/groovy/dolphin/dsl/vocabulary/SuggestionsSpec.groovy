package dolphin.dsl.vocabulary

import spock.lang.Specification

class SuggestionsSpec extends Specification {

    static final List<String> WORDS = ['takeOff', 'takeOffWithYaw', 'goPos', 'landingPoint', 'returnHomeAndLand', 'returnHome',
                                       'id', 'move', 'moveFromHome', 'delay', 'speed', 'count']

    def "the Levenshtein distance counts insertions, deletions and substitutions"() {
        expect:
        Suggestions.distance(a, b) == d

        where:
        a         | b         | d
        ''        | ''        | 0
        'abc'     | ''        | 3
        ''        | 'abc'     | 3
        'kitten'  | 'sitting' | 3
        'takeoff' | 'takeOff' | 1
        'goPos'   | 'goPos'   | 0
    }

    def "names within two edits, case aside, nearest first"() {
        expect:
        Suggestions.near(name, WORDS) == near

        where:
        name      | near
        'takeoff' | ['takeOff', 'takeOffWithYaw']
        'gopos'   | ['goPos']
        'delya'   | ['delay']
        'sped'    | ['speed']
        'spede'   | ['speed']
    }

    def "names of four letters or more also find the names that begin or end with them, shortest first, after the near ones"() {
        expect:
        Suggestions.near('land', WORDS) == ['landingPoint', 'returnHomeAndLand']
        Suggestions.near('home', WORDS) == ['move', 'returnHome', 'moveFromHome']
    }

    def "short names allow one edit only, so that v2 does not suggest id"() {
        expect:
        Suggestions.near('v2', WORDS) == []
        Suggestions.near('ix', WORDS) == ['id']
        Suggestions.near('mov', ['move', 'mouse']) == ['move']
    }

    def "at most three suggestions, never the name itself"() {
        given:
        def many = ['abcd', 'abce', 'abcf', 'abcg', 'abch']

        expect:
        Suggestions.near('abcx', many).size() == 3
        Suggestions.near('goPos', WORDS) == []
    }

    def "did you mean: the suggestions quoted and joined, or nothing"() {
        expect:
        Suggestions.didYouMean('gopos', WORDS) == "; did you mean 'goPos'?"
        Suggestions.didYouMean('land', WORDS) == "; did you mean 'landingPoint' or 'returnHomeAndLand'?"
        Suggestions.didYouMean('zzzzzz', WORDS) == ''
    }
}
