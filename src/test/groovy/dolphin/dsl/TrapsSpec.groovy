package dolphin.dsl

import dolphin.core.VehiclelessPlatform
import dolphin.dsl.check.QuickFix
import dolphin.platform.MAVLinkLanguage
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.testing.FixApplier.applied

/**
 * The traps of the Groovy embedding (docs/guide.md, "Groovy's traps"): layouts Groovy reads
 * differently from what they say. Each gets one finding that says how Groovy read the line and what to
 * write, with a fix that writes it; the fixed script checks clean and runs. The layouts next to them
 * that Groovy reads as they say get no finding.
 */
class TrapsSpec extends Specification {

    static final String FILE = 'traps.dolphin'

    ScriptHarness h = new ScriptHarness(2)

    def "the issue's script: a watch with its handler guards one of two vehicles' tasks; it checks clean and runs"() {
        given:
        String script = '''v1 = pick { }
v2 = pick { }
north = failing('north', 1, 'engine failure')
south = fly('south', 2)
execute v1: watch(north) onError { msg ->
          message "north failed: ${msg}"
          ignore()
        },
        v2: south
message 'after'
'''

        expect:
        h.engine.check(script, FILE) == []

        when:
        def result = h.run(script, FILE)

        then: 'the handler ran inside onError { }, and the second entry flew, concurrently'
        result.outcome == COMPLETED
        h.messages.contains('north failed: engine failure')
        h.messages.contains('after')
        h.events.any { it.toString().contains('south') }
    }

    def "#trap: one finding at line #line that says how Groovy read it and what to write; its fix checks clean and runs"() {
        when:
        List<ScriptError> found = h.engine.check(source, FILE)

        then:
        found.size() == 1
        found[0].line() == line
        found[0].message().contains(explains)
        found[0].fixes().size() == 1

        when:
        String corrected = applied(source, found[0].fixes()[0])

        then:
        corrected == fixed
        h.engine.check(corrected, FILE) == []
        h.run(corrected, FILE).outcome == COMPLETED

        where: 'every task runs on a key\'s vehicles: the test platform has no free vehicle for a task without one'
        trap                             | source                                                                                    | line || explains                                                          | fixed
        'execute alone on its line'      | "v1 = pick { }\nexecute\n    v1: fly('a', 1)\n"                                           | 2    || "'execute' stands alone on its line"                              | "v1 = pick { }\nexecute v1: fly('a', 1)\n"
        'then on the next line'          | "v1 = pick { }\nexecute v1: waitFor { true }\n    then fly('a', 1)\n"                     | 3    || "'then' begins a new statement"                                   | "v1 = pick { }\nexecute v1: waitFor { true } then fly('a', 1)\n"
        'onError on the next line'       | "v1 = pick { }\nt = watch failing('a', 1, 'x')\n    onError { ignore() }\nexecute v1: t\n" | 3 || "'onError' begins a new statement"                                | "v1 = pick { }\nt = watch failing('a', 1, 'x') onError { ignore() }\nexecute v1: t\n"
        'watch t after a key'            | "v1 = pick { }\nt = fly('a', 1)\nexecute v1: watch t onError { ignore() }\n"              | 3    || "'onError' is read here as an argument of what comes before it"   | "v1 = pick { }\nt = fly('a', 1)\nexecute v1: watch(t) onError { ignore() }\n"
        'watch t after one of two keys'  | "v1 = pick { }\nv2 = pick { }\nt = fly('a', 1)\nexecute v1: watch t onError { ignore() }, v2: fly('b', 1)\n" | 4 || "'onError' is read here as an argument" | "v1 = pick { }\nv2 = pick { }\nt = fly('a', 1)\nexecute v1: watch(t) onError { ignore() }, v2: fly('b', 1)\n"
        'an operator after onError { }'  | "v1 = pick { }\nt = failing('a', 1, 'x')\nexecute v1: watch(t) onError { ignore() } >> fly('b', 1)\n" | 3 || "'>> ...' after the onError block applies to the block, not to the watch" | "v1 = pick { }\nt = failing('a', 1, 'x')\nexecute v1: (watch(t) onError { ignore() }) >> fly('b', 1)\n"
        'a constraint after onError { }' | "v1 = pick { }\nt = failing('a', 1, 'x')\nexecute v1: watch(t) onError { ignore() } / { false }\n" | 3 || "'/ ...' after the onError block applies to the block" | "v1 = pick { }\nt = failing('a', 1, 'x')\nexecute v1: (watch(t) onError { ignore() }) / { false }\n"
        'an operator after an assigned watch' | "v1 = pick { }\nt = failing('a', 1, 'x')\nw = watch(t) onError { ignore() } >> fly('b', 1)\nexecute v1: w\n" | 3 || "'>> ...' after the onError block applies to the assignment" | "v1 = pick { }\nt = failing('a', 1, 'x')\nw = (watch(t) onError { ignore() }) >> fly('b', 1)\nexecute v1: w\n"
        'during 30 run after a key'      | "v1 = pick { }\nexecute v1: during 30 run fly('a', 1)\n"                                  | 2    || "Groovy reads 'during 30 run ...' after execute as more words of execute's own command chain" | "v1 = pick { }\nexecute v1: during(30) run fly('a', 1)\n"
        'during 30.seconds run, a key after' | "v1 = pick { }\nv2 = pick { }\nexecute v1: during 30.seconds run fly('a', 1), v2: fly('b', 1)\n" | 3 || "Expected the duration in parentheses: 'during(30.seconds) run ...'" | "v1 = pick { }\nv2 = pick { }\nexecute v1: during(30.seconds) run fly('a', 1), v2: fly('b', 1)\n"
        'an entry without its comma'     | "v1 = pick { }\nv2 = pick { }\nexecute v1: fly('a', 1)\n        v2: fly('b', 1)\n"       | 4    || "'v2:' is read as a label, not as an entry of the call on line 3" | "v1 = pick { }\nv2 = pick { }\nexecute v1: fly('a', 1),\n        v2: fly('b', 1)\n"
        'a parenthesis after execute'    | "v1 = pick { }\nexecute (fly('a', 1)[v1] >> fly('b', 1)[v1]) / { false }\n" | 2 || "Groovy takes the parentheses after 'execute' as its whole argument list" | "v1 = pick { }\nexecute((fly('a', 1)[v1] >> fly('b', 1)[v1]) / { false })\n"
        'a def key'                      | "def v1 = pick { }\nexecute v1: fly('a', 1)\n"                                            | 2    || "'v1' is declared with 'def'"                                     | "v1 = pick { }\nexecute v1: fly('a', 1)\n"
    }

    def "an operator after the onError block of a watch given to execute without a key: the fix adds the key '_:' too"() {
        given:
        String source = "t = failing('a', 1, 'x')\nexecute watch(t) onError { ignore() } / { false }\n"

        when:
        List<ScriptError> found = h.engine.check(source, FILE)

        then: 'a parenthesis right after execute would be the trap of execute (a) / { c }'
        found*.line() == [2]
        applied(source, found[0].fixes()[0]) == "t = failing('a', 1, 'x')\nexecute _: (watch(t) onError { ignore() }) / { false }\n"
        h.engine.check(applied(source, found[0].fixes()[0]), FILE) == []
    }

    def "a block after a variable goes to the variable: one finding, and its fix gives the block to the word"() {
        given:
        Engine engine = new Engine(new VehiclelessPlatform('none'))
        engine.addExtension(new MAVLinkLanguage())
        String source = "homePos = location(40.4, -7.3, 820)\np = move homePos { north 30 }\n"

        when:
        List<ScriptError> found = engine.check(source, FILE)

        then:
        found.size() == 1
        found[0].line() == 2
        found[0].message() == "'homePos { ... }' gives the block to homePos, which holds a Position, not a command: Groovy hands a" +
                " block to the name right before it, not to 'move'. Expected 'move(homePos) { ... }'"
        found[0].fixes()*.title() == ["Write 'move(homePos) { ... }'"]

        when:
        String corrected = applied(source, found[0].fixes()[0])

        then:
        corrected == "homePos = location(40.4, -7.3, 820)\np = move(homePos) { north 30 }\n"
        engine.check(corrected, FILE) == []
    }

    def "layouts Groovy reads as they say get no finding: #what"() {
        expect:
        h.engine.check(source, FILE) == []

        where:
        what                                  | source
        'watch(t) after one of two keys'      | "v1 = pick { }\nv2 = pick { }\nt = fly('a', 1)\nexecute v1: watch(t) onError { ignore() }, v2: fly('b', 1)\n"
        'watch(t) after the second key'       | "v1 = pick { }\nv2 = pick { }\nt = fly('a', 1)\nexecute v1: fly('b', 1), v2: watch(t) onError { ignore() }\n"
        'two watches after two keys'          | "v1 = pick { }\nv2 = pick { }\nexecute v1: watch(fly('a', 1)) onError { ignore() }, v2: watch(fly('b', 1)) onError { propagate() }\n"
        'waitFor then after one of two keys'  | "v1 = pick { }\nv2 = pick { }\nexecute v1: waitFor { true } then fly('a', 1), v2: fly('b', 1)\n"
        'the watch and its operator grouped'  | "v1 = pick { }\nexecute v1: (watch(fly('a', 1)) onError { ignore() }) >> fly('b', 1)\n"
        'entries on lines ending in commas'   | "v1 = pick { }\nv2 = pick { }\nexecute v1: fly('a', 1),\n        v2: fly('b', 1)\n"
        'a label on a loop'                   | "outer:\nfor (i in 1..2) {\n    for (j in 1..2) {\n        if (j == 2) continue outer\n    }\n}\n"
        'a variable holding a closure, given a block' | "twice = { Closure c -> c(); c() }\ntwice { message 'x' }\n"
        'execute with its task in parentheses' | "execute((fly('a', 1) >> fly('b', 1)) / { false })\n"
    }

    def "every 'did you mean' comes with a fix per name it suggests, replacing the wrong name at its place"() {
        given:
        Engine engine = new Engine(new VehiclelessPlatform('none'))
        engine.addExtension(new MAVLinkLanguage())

        when:
        List<ScriptError> found = engine.check(source, FILE)

        then:
        found.size() == 1
        found[0].message().contains('did you mean')
        found[0].fixes() == fixes

        where:
        source                                                                   || fixes
        "m = mission {\n  mvoe 50, 0\n}\n"                                       || [new QuickFix("Change 'mvoe' to 'move'", 2, 3, 2, 7, 'move')]
        "v1 = pick { }\nmessage \"${'$'}{batery(v1)}\"\n"                        || [new QuickFix("Change 'batery' to 'battery'", 2, 12, 2, 18, 'battery')]
        "pick { timeout 30.secondz }\n"                                          || [new QuickFix("Change 'secondz' to 'seconds'", 1, 19, 1, 26, 'seconds')]
        "homePos = location(1, 2, 3)\nmessage \"${'$'}{homePoz}\"\n"             || [new QuickFix("Change 'homePoz' to 'homePos'", 2, 12, 2, 19, 'homePos')]
        "execute waitFor { true } thne idle(1)\n"                                || [new QuickFix("Change 'thne' to 'then'", 1, 26, 1, 30, 'then')]
        "declareSensors 'SMOKE'\nv = pick { }\nx = sensor(v, 'SMOKY')\n"         || [new QuickFix("Change 'SMOKY' to 'SMOKE'", 3, 16, 3, 21, 'SMOKE')]
    }
}
