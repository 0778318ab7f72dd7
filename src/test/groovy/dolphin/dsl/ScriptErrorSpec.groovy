package dolphin.dsl

import dolphin.core.Task
import dolphin.testing.FlyTask
import dolphin.testing.ScriptHarness
import spock.lang.Specification

import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR

/**
 * Script errors name the file, the line and what was expected (design §7): compile-time mistakes
 * (found by Engine.check too) and run-time ones, mapped back to the script's line.
 */
class ScriptErrorSpec extends Specification {

    static final String FILE = 'missions/patrol.dolphin'

    ScriptHarness h = new ScriptHarness(2)

    private static int lineOf(String source, String fragment) {
        def lines = source.readLines()
        def at = lines.findIndexOf { it.contains(fragment) }
        assert at >= 0: "no line contains ${fragment}"
        at + 1
    }

    private ScriptError runError(String source) {
        def r = h.run(source, FILE)
        assert r.outcome == SCRIPT_ERROR
        assert r.error != null
        assert r.exitCode() == 1
        assert h.messages.contains(r.error.toString())          // the listener is told, file:line first
        r.error
    }

    def "compile-time mistake (#kind) is found by check and by run, with file, line and what was expected"() {
        when:
        def checked = h.engine.check(source, FILE)
        def error = runError(source)

        then:
        checked == [error]
        error.file == FILE
        error.line == lineOf(source, lineWith)
        error.message.contains(expected)
        error.toString().startsWith("${FILE}:${error.line}:")
        h.messages.every { !it.startsWith('picked') }             // nothing ran

        where:
        kind                  | source                                                                    | lineWith              || expected
        'unclosed brace'      | "v1 = pick {\n    type 'UAV'\n\nexecute v1: fly('a', 1)\n"               | 'pick {'              || "the '{' opened here is never closed: expected a '}'"
        'bare execute'        | "v1 = pick { }\nexecute\n    v1: fly('a', 1)\n"                          | 'execute'             || "Expected the first task on the same line"
        'execute key is def'  | "def v1 = pick { }\nmessage 'x'\nexecute v1: fly('a', 1)\n"              | 'execute v1'          || "Expected an assignment without 'def', e.g. 'v1 = pick { ... }'"
        'chained key is def'  | "v1 = pick { }\ndef v2 = pick { }\nexecute v1: waitFor { true } then fly('a', 1),\n        v2: fly('b', 1)\n" | 'v2: fly' || "'v2' is declared with 'def'"
        "then on a new line"  | "v1 = pick { }\nexecute v1: waitFor { true }\n    then fly('a', 1)\n"    | 'then fly'            || "Expected 'then' on the same line"
        "run on a new line"   | "v1 = pick { }\nt = until { false }\n    run fly('a', 1)\n"               | 'run fly'             || "Expected 'run' on the same line"
        "onError on new line" | "v1 = pick { }\nt = watch fly('a', 1)\n    onError { ignore() }\n"       | 'onError'             || "Expected 'onError' on the same line"
        "onError as argument" | "v1 = pick { }\nt = fly('a', 1)\nexecute v1: watch t onError { ignore() }\n" | 'watch t'      || "'onError' is read here as an argument of what comes before it"
        "execute (a) / {c}"   | "v1 = pick { }\nexecute (fly('a', 1) >> fly('b', 1)) / { false }\n"    | 'execute ('           || "'/ { condition }' would apply to execute's result after the task ran without it"
        "execute (a) >> b"    | "v1 = pick { }\nx = 1\nexecute (fly('a', 1)) >> fly('b', 1)\n"          | 'execute ('           || "Expected the whole task inside execute's parentheses, e.g. 'execute((a >> b) >> task)'"
    }

    def "the def-key error also gives the column"() {
        when:
        def errors = h.engine.check("def v1 = pick { }\nexecute   v1: fly('a', 1)", FILE)

        then:
        errors*.line == [2]
        errors*.column == [11]
        errors[0].toString().startsWith("${FILE}:2:11: execute: 'v1' is declared with 'def'")
    }

    def "run-time mistake (#kind) names the file, the line and what was expected"() {
        given:
        h.engine.addExtension(new DslExtension() {
            List<Object> words(ScriptContext context) { [new MissionWords(h)] }
        })

        when:
        def error = runError(source)

        then:
        error.file == FILE
        error.line == lineOf(source, lineWith)
        error.message.contains(expected)

        where:
        kind                         | source                                                                   | lineWith          || expected
        'unknown DSL word'           | "v1 = pick { }\n\ntakeoff 100\n"                                         | 'takeoff'         || "unknown command 'takeoff' with arguments (Integer); did you mean 'takeOff'?"
        'unknown word: what is ok'   | "v1 = pick { }\nmesage 'hi'\n"                                           | 'mesage'          || "Expected a DSL word, a Groovy method or a closure variable"
        'unknown variable'           | "v1 = pick { }\nexecute fly('a', 1)[V1]\n"                               | 'V1'              || "unknown name 'V1'; did you mean 'v1'"
        'unknown variable: what is ok'| "x = nosuch + 1\n"                                                      | 'nosuch'          || "Expected a variable assigned in the script"
        'execute key not assigned'   | "v1 = pick { }\nexecute vx: fly('a', 1)\n"                               | 'vx'              || "no script variable named 'vx'. Keys name vehicle sets held in script variables assigned without 'def', e.g. vx = pick { ... }"
        'execute key not a NodeSet'  | "v1 = pick { }\nn = 3\nexecute n: fly('a', 1)\n"                         | 'execute n'       || "the key 'n' does not identify a vehicle set: it holds Integer"
        'position of two vehicles'   | "vs = pick { count 2 }\n\np = position(vs)\n"                            | 'position'        || 'position: the vehicle set must hold exactly one vehicle, but it holds 2'
        'battery of two vehicles'    | "vs = pick { count 2 }\nok = battery(vs) > 0.5\n"                        | 'battery'         || 'battery: the vehicle set must hold exactly one vehicle, but it holds 2'
        'latitude out of range'      | "home = location(40.4, -7.3)\nbad = location(140.4, -7.3)\n"             | '140.4'           || 'location: the latitude must be between -90 and 90 degrees, got 140.4'
        'connection timeout'         | "v1 = pick { }\nsetConnectionTimeout 2\n"                                | 'setConnection'   || 'connection timeout must be between 5 and 3600 seconds, got 2.0'
        'connection timeout map'     | "v1 = pick { }\nsetConnectionTimeout v1: 2.hours\n"                      | 'setConnection'   || 'connection timeout must be between 5 and 3600 seconds, got 7200.0'
        'pick count 0'               | "v1 = pick {\n  type 'UAV'\n  count 0\n}\n"                              | 'count 0'         || 'pick: count must be positive, got 0'
        'pick count -2'              | "v1 = pick {\n  type 'UAV'\n  count -2\n}\n"                             | 'count -2'        || "'count' is a command of pick { }, but Groovy read it as a variable here: write it with its arguments, as in count(n); a negative value needs parentheses, 'count(-2)' (Groovy reads 'count -2' as 'count minus 2')"
        'vehicle set plus a number'  | "v1 = pick { }\nv2 = v1 + 3\n"                                          | 'v1 + 3'          || 'a vehicle set + a Integer (3): vehicle sets combine only with vehicle sets, e.g. v1 + v2'
        'command used as variable'   | "v1 = pick { }\nt = idle\nexecute v1: t\n"                                | 'idle'            || "'idle' is a command, but Groovy read it as a variable here. Expected it with its arguments"
        'wrong argument type'        | "v1 = pick { }\nexecute idle('five')\n"                                  | 'five'            || "wrong arguments for 'idle': got (String); expected (Number)"
        'operator misuse'            | "v1 = pick { }\nt = fly('a', 1) >> 5\n"                                  | '>> 5'            || "the operator '>>' does not apply to FlyTask and Integer: expected tasks with >> and |"
        'waitFor without then'       | "v1 = pick { }\nexecute v1: waitFor { true }\nmessage 'x'\n"             | 'waitFor'         || "execute: the entry 'v1: waitFor { ... }' has no 'then' part. Expected 'waitFor { ... } then ...'"
        'no vehicles for the task'   | "execute fly('a', 1)\n"                                                  | 'fly'             || "no vehicles to run task a"
        'error in a guard, later'    | "v1 = pick { }\nt = waitFor {\n  battery(v1 + nosuch) > 1\n} then fly('a', 1)\nexecute t\n" | 'nosuch' || "unknown name 'nosuch'"
    }

    def "a pick block still reads the script's variables, and a well-formed execute with parentheses runs"() {
        when:
        def r = h.run("n = 1\nv1 = pick { count n; timeout 0 }\nexecute((fly('a', 1) >> fly('b', 1)) / { false })\n", FILE)

        then:
        r.outcome == COMPLETED
        h.platform.journal*.kind.count('start') == 2
    }

    def "check sees a variable never assigned, even in an expression it cannot evaluate"() {
        expect:
        h.engine.check("v1 = pick { }\np = position(v1 + v1 + nosuch)", FILE)*.line == [2]
    }

    def "the script's file name may be a bare name, a path, a Windows path or a variable's name: line numbers are found for each"() {
        when:
        def r = h.run("x = 1\ny = nosuch\n", file)

        then:
        r.error.file == file
        r.error.line == 2

        where:
        file << ['patrol.dolphin', '/abs/dir/patrol.dolphin', 'C:\\missions\\patrol.dolphin', 'no-extension', 'long.dolphin', 'x.dolphin']
    }

    def "ScriptResult and ScriptError read as file:line: message"() {
        when:
        def r = h.run("v1 = pick { }\nhome = location(91, 0)\n", FILE)

        then:
        r.error.toString() == "${FILE}:2: location: the latitude must be between -90 and 90 degrees, got 91".toString()
        r.toString() == "SCRIPT_ERROR: ${r.error}".toString()
        r.message == r.error.message
    }

    /** A stand-in for the MAVLink words, so that 'takeoff' has a close match. */
    static class MissionWords {
        final ScriptHarness h

        MissionWords(ScriptHarness h) { this.h = h }

        Task takeOff(Number height) { new FlyTask(h.platform, 'takeOff', 1) }
    }
}
