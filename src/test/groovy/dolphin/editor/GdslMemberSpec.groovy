package dolphin.editor

import dolphin.dsl.DolphinScript
import dolphin.dsl.vocabulary.Param
import dolphin.dsl.vocabulary.Signature
import dolphin.dsl.vocabulary.WordEntry
import dolphin.core.Position
import spock.lang.Specification

class GdslMemberSpec extends Specification {

    def "types by the names IntelliJ reads: nested classes with a dot, arrays with brackets, primitives as they are"() {
        expect:
        GdslMember.typeName(type) == name

        where:
        type               | name
        DolphinScript.Then | 'dolphin.dsl.DolphinScript.Then'
        Position[]         | 'dolphin.core.Position[]'
        double             | 'double'
        void               | 'void'
        Closure            | 'groovy.lang.Closure'
    }

    def "a Groovy string literal keeps quotes and backslashes"() {
        expect:
        GdslMember.literal("the vehicle's") == "'the vehicle\\'s'"
        GdslMember.literal('.*\\.dolphin') == "'.*\\\\.dolphin'"
        Eval.me(GdslMember.literal("a 'b' \\c \$d")) == "a 'b' \\c \$d"
    }

    def "one method line per form, the shortest first, with the units of the parameters not named after them"() {
        given:
        def lat = new Param('lat', Number, 'degrees', null)
        def lon = new Param('lon', Number, 'degrees', null)
        def hae = new Param('hae', Number, 'metres above mean sea level', null)
        def word = new WordEntry('goPos', 'A waypoint <here> & there', [new Signature([lat, lon, hae], false, void),
                                                                        new Signature([lat, lon], false, void)], false)
        def metres = new WordEntry('north', 'Metres north', [new Signature([new Param('metres', Number, 'metres', null)], false, void)], false)

        expect:
        GdslMember.methods(word) == [
                "method name: 'goPos', type: 'void', params: [lat: 'java.lang.Number', lon: 'java.lang.Number'], "
                        + "doc: 'A waypoint &lt;here&gt; &amp; there<br>lat: degrees, lon: degrees'",
                "method name: 'goPos', type: 'void', params: [lat: 'java.lang.Number', lon: 'java.lang.Number', hae: 'java.lang.Number'], "
                        + "doc: 'A waypoint &lt;here&gt; &amp; there<br>lat: degrees, lon: degrees, hae: metres above mean sea level'"]
        GdslMember.methods(metres) == ["method name: 'north', type: 'void', params: [metres: 'java.lang.Number'], doc: 'Metres north'"]
    }

    def "a word without parameters has an empty map; a unit is a property of the units' type"() {
        given:
        def stop = new WordEntry('stopCapturing', 'Stops taking photos', [new Signature([], false, void)], false)
        def km = new WordEntry('km', 'Kilometres, as metres', [], true)

        expect:
        GdslMember.methods(stop) == ["method name: 'stopCapturing', type: 'void', params: [:], doc: 'Stops taking photos'"]
        GdslMember.property(km) == "property name: 'km', type: 'double', doc: 'Kilometres, as metres'"
    }
}
