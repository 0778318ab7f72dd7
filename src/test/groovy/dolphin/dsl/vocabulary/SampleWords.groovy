package dolphin.dsl.vocabulary

import dolphin.core.Position

/**
 * Words made up to show how the vocabulary reads methods: Groovy's default arguments, overloads,
 * varargs, blocks and a word that leads to another.
 */
class SampleWords {

    @Word('A waypoint')
    void goPos(Number lat, Number lon, Number hae = 0) {}

    @Word('A waypoint')
    void goPos(Position position) {}

    @Word('Nested optionals')
    void loiterTurns(Number lat, Number lon, Number hae, Number turns = 10, Number radius = 15) {}

    @Word('Independent optionals')
    void surveyArea(Number length, Number width) {}

    @Word('Independent optionals')
    void surveyArea(Number length, Number width, Number spacing) {}

    @Word('Independent optionals')
    void surveyArea(Number length, Number width, String direction) {}

    @Word('Independent optionals')
    void surveyArea(Number length, Number width, Number spacing, String direction) {}

    @Word('Any number of positions')
    void rally(Position... points) {}

    @Word('A block of sample words')
    void block(@DelegatesTo(SampleBlockWords) Closure commands) {}

    @Word('A position and a block')
    void around(Position position, @DelegatesTo(SampleBlockWords) Closure offset) {}

    @Word('Nothing to give')
    void stop() {}

    @Word('A word after which then comes')
    SampleChainWords wait(Closure condition) { new SampleChainWords() }

    /** Not a word: no @Word. */
    void helper(Number x) {}
}

class SampleBlockWords {

    @Word('Metres north')
    void north(Number metres) {}

    @Word('An opinion without a unit')
    void speedish(Number howFast) {}
}

class SampleChainWords {

    @Word('The second half')
    void then(Object task) {}
}

class SampleUnits {

    @Word('Furlongs, as metres')
    static double getFurlongs(Number n) { n.doubleValue() * 201.168 }

    /** Not a unit: no @Word. */
    static double getLeagues(Number n) { n.doubleValue() * 4828 }
}
