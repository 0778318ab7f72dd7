package dolphin.dsl.vocabulary

import dolphin.dsl.DolphinScript
import dolphin.dsl.GuardedTaskSetBuilder
import dolphin.dsl.Picker
import dolphin.mission.dsl.FenceBuilder
import dolphin.mission.dsl.MissionBuilder
import dolphin.mission.dsl.NedBuilder
import dolphin.mission.dsl.PositionBuilder
import spock.lang.Shared
import spock.lang.Specification

class VocabularySpec extends Specification {

    @Shared
    Vocabulary language = LanguageWords.vocabulary()

    def "every number parameter of every word has a unit or counts something"() {
        expect:
        language.parametersWithoutUnits() == []
    }

    def "a number parameter whose name says no unit is reported, with its class and word"() {
        given:
        def sample = Vocabulary.of(SampleWords, [], [SampleUnits])

        expect:
        sample.parametersWithoutUnits() == ['SampleBlockWords.speedish(howFast)']
    }

    def "units come from the parameter's name: one name, one unit across the language"() {
        given:
        def goPos = language.scopeOf(MissionBuilder).get().words().goPos
        def params = goPos.signatures().collectMany { it.params() }.collectEntries { [it.name(), it.unit()] }

        expect:
        params == [position: '', lat: 'degrees', lon: 'degrees', hae: 'metres above mean sea level']
        language.scopeOf(MissionBuilder).get().words().speed.signatures()*.params().flatten()
                .collectEntries { [it.name(), it.unit()] } == [newSpeed: 'm/s', speedType: '']
    }

    def "the script's top level: the base class's words, the platform's and the imported ones"() {
        given:
        def script = language.script()

        expect:
        script.kind() == WordScope.ScopeKind.SCRIPT
        script.type() == DolphinScript
        script.openers() == []
        script.words().keySet().containsAll(['pick', 'execute', 'waitFor', 'release', 'location', 'halt'])
        script.words().keySet().containsAll(['sendMessage', 'downloadMission', 'fenceBreached', 'missionFromFile', 'move'])
        script.words().keySet().containsAll(['mission', 'pos', 'moveDistance'])
        script.where() == "at the script's top level"
        language.scopes().first().is(script)
    }

    def "blocks: the words a closure opens, found from the @DelegatesTo of the words that take it"() {
        expect:
        def scope = language.scopeOf(type).get()
        scope.kind() == WordScope.ScopeKind.BLOCK
        scope.openers() == openers
        scope.where() == where

        where:
        type                  | openers                      | where
        MissionBuilder        | ['mission']                  | 'inside mission { }'
        FenceBuilder          | ['fence']                    | 'inside fence { }'
        Picker                | ['pick']                     | 'inside pick { }'
        NedBuilder            | ['move', 'moveDistance']     | 'inside move { } or moveDistance { }'
        PositionBuilder       | ['pos']                      | 'inside pos { }'
        GuardedTaskSetBuilder | ['allOf', 'choose', 'oneOf'] | 'inside allOf { }, choose { } or oneOf { }'
        DolphinScript.ErrorDecision | ['onError']            | 'inside onError { }'
    }

    def "a block inside a block: fence is a word of mission { } and opens its own"() {
        expect:
        language.scopeOf(MissionBuilder).get().words().fence.usages() == ['fence { regions }']
        !language.script().words().containsKey('fence')
        language.scopesWith('fence')*.type() == [MissionBuilder]
    }

    def "chains: the words after a word, of the class it returns"() {
        expect:
        def scope = language.scopeOf(type).get()
        scope.kind() == WordScope.ScopeKind.CHAIN
        scope.openers() == openers
        scope.words().keySet() == [word] as Set
        scope.where() == where

        where:
        type                  | openers              | word      | where
        DolphinScript.Then    | ['waitFor', 'when']  | 'then'    | 'after waitFor or when'
        DolphinScript.Run     | ['during', 'until']  | 'run'     | 'after during or until'
        DolphinScript.OnError | ['watch']            | 'onError' | 'after watch'
    }

    def "the units: the categories' getters, read as properties of numbers"() {
        given:
        def units = language.units()

        expect:
        units.kind() == WordScope.ScopeKind.UNITS
        units.type() == Number
        units.words().keySet() == ['days', 'degrees', 'east', 'hours', 'kilometers', 'km', 'meters', 'minutes', 'north',
                                   'percent', 'radians', 'seconds', 'south', 'west'] as Set
        units.words().minutes.usages() == ['n.minutes']
        units.words().minutes.forms() == []
        units.words().minutes.unit()
        units.where() == 'after a number, as in 10.minutes'
        language.scopes().last().is(units)
    }

    def "made-up words: a block, a chain and a unit found the same way, words without @Word left out"() {
        given:
        def sample = Vocabulary.of(SampleWords, [], [SampleUnits])

        expect:
        sample.scopeOf(SampleBlockWords).get().openers() == ['around', 'block']
        sample.scopeOf(SampleChainWords).get().kind() == WordScope.ScopeKind.CHAIN
        sample.scopeOf(SampleChainWords).get().openers() == ['wait']
        sample.units().words().keySet() == ['furlongs'] as Set
        !sample.script().words().containsKey('helper')
        !sample.scopeOf(String).present
    }

    def "a word in several scopes, and every name once, sorted"() {
        expect:
        language.scopesWith('move')*.type() == [DolphinScript, MissionBuilder]
        language.scopesWith('north')*.type() == [NedBuilder, Number]
        language.names() == language.names().toSorted()
        language.names().toSet().size() == language.names().size()
        language.names().containsAll(['pick', 'goPos', 'then', 'polygon', 'km', 'lat', 'ignore', 'when'])
    }

    def "a word's forms are its usages' parameters: what messages print after the name"() {
        given:
        def words = language.scopeOf(MissionBuilder).get().words()

        expect:
        words.loiterPos.formsText() == '(lat, lon, hae[, radius]) or (position[, radius])'
        words.surveyArea.usages() == ['surveyArea(base, length, width[, spacing][, direction])',
                                      'surveyArea(length, width[, spacing][, direction])']
        words.rally.usages() == ['rally(points...)']
    }
}
