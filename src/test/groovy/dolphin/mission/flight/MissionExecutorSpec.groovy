package dolphin.mission.flight

import dolphin.dsl.Engine
import dolphin.dsl.EngineListener
import dolphin.dsl.ScriptResult
import dolphin.mavlink.FleetHarness
import dolphin.platform.MAVLinkPlatform
import dolphin.sim.SimOptions
import dolphin.sim.VehicleKind
import java.time.Duration
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout

/** Missions flown end to end: a script, the MissionExecutor, the protocols, simulated vehicles over UDP. */
@Timeout(120)
class MissionExecutorSpec extends Specification {

    @AutoCleanup
    FleetHarness h = new FleetHarness()
    List<String> messages = new java.util.concurrent.CopyOnWriteArrayList()

    static final String HOP = '''
        hop = mission {
            name 'hop'
            takeOff location(40.444233, -7.375234, 840)
            goPos 40.4446, -7.375234, 840
            landingPoint 40.4446, -7.375234, 820
        }
    '''

    ScriptResult run(String script) {
        def engine = new Engine(new MAVLinkPlatform(h.comms), h.clock)
        engine.addListener(new EngineListener() {
            void message(String text) { messages << text }
        })
        def result = engine.run(script, 'fly.dolphin').await(Duration.ofSeconds(100))
        assert result != null: "script did not end; messages: ${messages}"
        result
    }

    def "a copter flies a mission to its landing: uploaded, verified, armed in GUIDED, started, landed and disarmed"() {
        given:
        def fleet = h.fleet(1)

        when:
        def result = run(HOP + '''
            v = pick { timeout 10 }
            r = execute v: hop
            message "result: ${r}"
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('result: DONE')
        ['uploading 4 items', 'upload verified', 'armed', 'started', 'done'].every { step ->
            messages.any { it == "mission hop on vehicle 1: ${step}".toString() }
        }
        with(fleet.vehicle(1)) {
            !armed()
            position().distanceTo(dolphin.core.Position.fromDegrees(40.4446, -7.375234, 820)) < 2
            mission().size() == 4
        }
    }

    def "a mission cut short by a condition sends its vehicle home (RTL), and the next mission flies"() {
        given:
        def fleet = h.fleet(1)

        when:
        def result = run(HOP + '''
            back = mission { name 'back'; home location(40.444233, -7.375234, 820); returnHomeAndLand() }
            v = pick { timeout 10 }
            execute v: (hop / { position(v).hae > 835 }) >> back
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('mission hop on vehicle 1: cut short: RTL')
        messages.contains('mission back on vehicle 1: done')
        !fleet.vehicle(1).armed()
    }

    def "a vehicle that never becomes ready: waited for, then an ERROR, seen by watch"() {
        given: 'a vehicle without a position estimate for 10 minutes (it says so 15 s after boot), and a 40 s readiness deadline'
        h.comms.missionExecutorConfig = MissionExecutorConfig.DEFAULT.withPrepare(Duration.ofSeconds(40))
        h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT.withWarmup(600))

        when:
        def result = run(HOP + '''
            v = pick { timeout 10 }
            execute v: watch(hop) onError { msg -> message "caught: ${msg}"; ignore() }
        ''')

        then: 'it said what it waited for, uploaded nothing, and ended in ERROR saying so'
        result.outcome == ScriptResult.Outcome.COMPLETED
        // which comes first depends on whether the vehicle's text (15 s after its boot) came before the mission began
        messages.contains('waiting for vehicle 1: PreArm: Need Position Estimate')
        !messages.any { it.contains('uploading') }
        messages.contains('caught: mission hop on vehicle 1: vehicle 1 was not ready within 40 s: PreArm: Need Position Estimate')
    }

    def "a vehicle started with the script: the mission waits until it is ready, then flies"() {
        given: 'a copter failing its pre-arm checks for its first 30 s, as ArduPilot after boot'
        def fleet = h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT.withWarmup(30))

        when:
        def result = run(HOP + '''
            base = location(40.444233, -7.375234, 820)
            hopHome = mission { name 'hop'; home base; takeOff location(40.444233, -7.375234, 840); landingPoint base }
            v = pick { timeout 10 }
            r = execute v: hopHome
            message "result: ${r}"
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('result: DONE')
        messages.any { it.startsWith('waiting for vehicle 1: ') }
        messages.any { it ==~ /mission hop on vehicle 1: vehicle ready after \d+ s/ }
        !fleet.vehicle(1).armed()
    }

    def "one mission object flies on two vehicles at once (E-3)"() {
        given:
        def fleet = h.fleet(2)

        when:
        def result = run(HOP + '''
            v1 = pick { timeout 10 }
            v2 = pick { timeout 10 }
            execute v1: hop, v2: hop
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('mission hop on vehicle 1: done')
        messages.contains('mission hop on vehicle 2: done')
        fleet.vehicles().every { !it.armed() && it.mission().size() == 4 }
    }

    def "a battery threshold cuts the mission of the right vehicle, which flies home; the other vehicle finishes"() {
        given: 'two copters; batteries drain 14 % per minute while armed'
        def fleet = h.fleet(2)

        when:
        def result = run(HOP + '''
            back = mission { name 'back'; home location(40.444233, -7.375234, 820); returnHomeAndLand() }
            v1 = pick { id '1'; timeout 10 }
            v2 = pick { id '2'; timeout 10 }
            execute v1: (hop / { battery(v1) < 0.97 }) >> back, v2: hop
            message "batteries: ${battery(v1)}, ${battery(v2)}"
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('mission hop on vehicle 1: cut short: RTL')
        !messages.contains('mission hop on vehicle 2: cut short: RTL')
        messages.contains('mission back on vehicle 1: done')
        messages.contains('mission hop on vehicle 2: done')
        fleet.vehicles().every { !it.armed() }
        fleet.vehicle(1).position().distanceTo(dolphin.core.Position.fromDegrees(40.444233, -7.375234, 820)) < 2
    }
}
