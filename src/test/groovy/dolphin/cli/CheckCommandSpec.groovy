package dolphin.cli

import spock.lang.Specification

class CheckCommandSpec extends Specification {

    static String script(String name) {
        new File(CheckCommandSpec.getResource("/scripts/${name}").toURI()).path
    }

    Map check(String... args) {
        def out = new StringWriter()
        def err = new StringWriter()
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(['check', *args] as String[])
        [code: code, out: out.toString(), err: err.toString()]
    }

    def "a correct script: no output, exit 0"() {
        when:
        def r = check(script('good.dolphin'))

        then:
        r.code == 0
        r.out.isEmpty()
        r.err.isEmpty()
    }

    def "a script with a mistake: file:line and what was expected, exit 1"() {
        when:
        def r = check(script(file))

        then:
        r.code == 1
        r.err.contains("${script(file)}:${line}")
        r.err.contains(fragment)

        where:
        file                   | line | fragment
        'bare-execute.dolphin' | 4    | "'execute' stands alone on its line"
        'syntax-error.dolphin' | 1    | "the '{' opened here is never closed: expected a '}'"
        'def-key.dolphin'      | 2    | "'v1' is declared with 'def'"
        'below-home.dolphin'   | 9    | "mission hop: item 2 (goPos, NAV_WAYPOINT) is 0.0 m above home (home at 820.0 m): lower than the 2 m clearance"
    }

    def "a new user's first script: every mistake at its line, with what was meant, before any vehicle is picked"() {
        when:
        def r = check(script('first-try.dolphin'))

        then:
        r.code == 1
        r.err.readLines() == [
                "${script('first-try.dolphin')}:3:3: takeOff: expected (position[, pitch]), got (Integer); a position is pos { lat ...; lon ...; hae ... } or location(lat, lon, hae)",
                "${script('first-try.dolphin')}:4:3: unknown command 'mvoe' in mission { }; did you mean 'move'?",
                "${script('first-try.dolphin')}:5:3: unknown command 'land' in mission { }; did you mean 'landOnRunway' or 'landingPoint' or 'landVertically'?",
                "${script('first-try.dolphin')}:7:23: unknown command 'batery'; did you mean 'battery'?"]*.toString()
    }

    def "sensor words: a name no vehicle can send and a telemetry field MAVLink lacks; any other name may be read"() {
        when:
        def r = check(script('sensor-names.dolphin'))

        then:
        r.code == 1
        r.err.readLines() == [
                "${script('sensor-names.dolphin')}:3:7: sensorKnown: 'TEMPERATURE' has 11 characters: NAMED_VALUE_FLOAT names have at most 10," +
                        " so no vehicle can send it (did the sender cut it to 'TEMPERATUR'?)",
                "${script('sensor-names.dolphin')}:4:9: telemetry: VFR_HUD has no field groundsped; did you mean 'groundspeed'?" +
                        ' (its fields: airspeed, groundspeed, heading, throttle, alt, climb)']*.toString()
    }

    def "with a fleet file that lists the sensors, a name it does not declare is a mistake, with what it declares"() {
        given:
        String fleet = new File(CheckCommandSpec.getResource('/fleets/smoke-fleet.json').toURI()).path

        when:
        def r = check('--fleet', fleet, script('sensor-names.dolphin'))

        then:
        r.code == 1
        r.err.readLines()[0] == "${script('sensor-names.dolphin')}:2:11: sensor: no sensor 'SMOKY' is declared" +
                " (declared: DISTANCE_DOWN, DISTANCE_FWD, SMOKE); did you mean 'SMOKE'?"
        r.err.readLines().size() == 3
    }

    def "a script that declares its sensors: a misspelt one is a mistake without a fleet file"() {
        when:
        def r = check(script('sensor-declared.dolphin'))

        then:
        r.code == 1
        r.err.readLines() == ["${script('sensor-declared.dolphin')}:3:50: sensor: no sensor 'C02' is declared" +
                " (declared: CO2, DISTANCE_DOWN, DISTANCE_FWD, SMOKE); did you mean 'CO2'?"]*.toString()
    }

    def "a fleet file with a mistake stops the check at once, naming the file and the entry"() {
        given:
        def bad = File.createTempFile('fleet', '.json')
        bad.text = '{"vehicles": [{"sysid": 300}]}'

        when:
        def r = check('--fleet', bad.path, script('good.dolphin'))

        then:
        r.code == 2
        r.err.contains("${bad.path}: vehicle 1: sysid must be a system id from 1 to 255, got 300")

        cleanup:
        bad.delete()
    }

    def "missions built after a pick are checked: the rehearsal picks stand-ins and runs no execute, even in a loop"() {
        when:
        def r = check(script('below-home-after-pick.dolphin'))

        then:
        r.code == 1
        r.err.trim() == "${script('below-home-after-pick.dolphin')}:8: mission MissionPlan_line5: item 2 (goPos, NAV_WAYPOINT) is -10.0 m above home (home at 100.0 m): lower than the 2 m clearance, into the ground or nearly; only landings go lower. Raise it, or write 'allowBelowHome true' in the mission if this is intended"
    }

    def "what only a vehicle can tell ends the rehearsal quietly: no finding, exit 0"() {
        when:
        def r = check(script('mission-after-telemetry.dolphin'))

        then:
        r.code == 0
        r.err.isEmpty()
    }

    def "an unreadable script is a usage error, exit 2"() {
        when:
        def r = check('no/such/script.dolphin')

        then:
        r.code == 2
        r.err.contains('cannot read no/such/script.dolphin: no such file')
    }

    def "no command or an unknown option is a usage error, exit 2"() {
        expect:
        check(args as String[]).code == 2

        where:
        args << [['--frobnicate', 'x.dolphin'], []]
    }

    def "no command at all lists the commands"() {
        when:
        def err = new StringWriter()
        int code = Main.commandLine(new PrintWriter(new StringWriter()), new PrintWriter(err)).execute()

        then:
        code == 2
        err.toString().contains('Missing command: expected one of run, sim, check, mission, help')
    }
}
