package dolphin.mission.flight

import dolphin.mission.model.Mission
import dolphin.mission.model.MissionItem
import dolphin.mission.transfer.MissionTransferConfig
import dolphin.mission.transfer.MissionVerification
import dolphin.dsl.Engine
import dolphin.dsl.EngineListener
import dolphin.dsl.ScriptResult
import dolphin.mavlink.FleetHarness
import dolphin.mavlink.MAVLinkConfig
import dolphin.platform.MAVLinkPlatform
import dolphin.sim.FaultModel
import dolphin.sim.SimOptions
import dolphin.sim.SimVehicle
import dolphin.sim.VehicleKind
import java.time.Duration
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

/**
 * Missions flown end to end under faults: a lossy, duplicating or reordering link, a vehicle that
 * refuses to arm or to change mode, a vehicle lost or switched out of AUTO mid-mission. Faults in
 * the middle of a flight are injected by a thread that waits (with a deadline) for the executor's
 * progress messages, never by sleeping.
 */
@Timeout(120)
class MissionExecutorFaultsSpec extends Specification {

    static final int LOITER = 5   // COPTER_MODE_LOITER

    /**
     * The executor is RUNNING and has seen the vehicle fly in AUTO: it reports the items reached as
     * "at least k", so the first report may name any item before the landing.
     */
    static final Closure<Boolean> RUNNING = { String m -> m ==~ /mission hop on vehicle 1: item [1-3] of 4 reached/ }

    @AutoCleanup
    FleetHarness h = new FleetHarness()
    List<String> messages = new java.util.concurrent.CopyOnWriteArrayList()
    Engine engine
    List<Throwable> injectorFailures = new java.util.concurrent.CopyOnWriteArrayList()

    static final String HOP = '''
        hop = mission {
            name 'hop'
            takeOff location(40.444233, -7.375234, 840)
            goPos 40.4444, -7.375234, 840
            goPos 40.4446, -7.375234, 840
            landingPoint 40.4446, -7.375234, 820
        }
    '''

    ScriptResult run(String script) {
        engine = new Engine(new MAVLinkPlatform(h.comms), h.clock)
        engine.addListener(new EngineListener() {
            void message(String text) { messages << text }
        })
        def result = engine.run(script, 'fly.dolphin').await(Duration.ofSeconds(100))
        assert result != null: "script did not end; messages: ${messages}"
        result
    }

    /** Runs {@code action} on another thread as soon as a message matching {@code wanted} arrives (60 s real-time deadline). */
    Thread onMessage(Closure<Boolean> wanted, Closure action) {
        Thread t = Thread.start {
            long end = System.nanoTime() + 60_000_000_000L
            try {
                while (!seen(wanted)) {
                    if (System.nanoTime() > end) {
                        throw new AssertionError("no awaited message within 60 s; messages: ${messages}")
                    }
                    Thread.sleep(5)
                }
                action()
            } catch (Throwable e) {
                injectorFailures << e
            }
        }
        t
    }

    /** The script thread adds messages meanwhile: a copy-on-write list is iterated on a snapshot. */
    boolean seen(Closure<Boolean> wanted) {
        messages.any(wanted)
    }

    static List<String> diffs(List<MissionItem> intended, List<MissionItem> stored) {
        MissionVerification.firstDifference(intended, stored).map { [it] }.orElse([])
    }

    @Unroll
    def "fault: #fault -> #outcome #fragment"() {
        given:
        if (attempts) {
            h.close()
            h = new FleetHarness(MAVLinkConfig.of('udpin:127.0.0.1:0').withCommandAttempts(attempts))
        }
        if (executorConfig) {
            h.comms.missionExecutorConfig = executorConfig
        }
        if (tries) {
            h.comms.missionTransferConfig = new MissionTransferConfig(MissionTransferConfig.DEFAULT.timeout(), tries)
        }
        def fleet = h.fleet(1, VehicleKind.COPTER, 1, options, faults)
        SimVehicle vehicle = fleet.vehicle(1)
        Thread injector = inject ? onMessage(RUNNING) { inject(vehicle) } : null

        when:
        def result = run(HOP + """
            v = pick { timeout 10 }
            setConnectionTimeout v: ${timeout}
            execute v: watch(hop) onError { msg -> message "caught: \${msg}"; ignore() }
        """)
        injector?.join(10_000)

        then:
        injectorFailures.empty
        !injector?.alive
        result.outcome == ScriptResult.Outcome.COMPLETED

        and: 'DONE with the intended mission stored on the vehicle, or ERROR with the expected text'
        if (outcome == 'DONE') {
            assert messages.contains('mission hop on vehicle 1: done'): messages
            assert !messages.any { it.startsWith('caught:') }: messages
            assert diffs(((Mission) engine.variable('hop')).items(vehicle.home()), vehicle.mission()) == []
            assert !vehicle.armed()
        } else {
            assert !messages.contains('mission hop on vehicle 1: done'): messages
            String caught = messages.find { it.startsWith('caught: ') }
            assert caught != null: messages
            assert caught.contains(fragment)
        }

        // At 20 % loss both ways a command unheard after 12 attempts (0.2^12) or an upload the vehicle
        // cancels after eight unanswered requests (0.36^8 per item) are rare enough for a test that must
        // not flake; at 30 % ArduPilot's own 8 s upload timeout already cancels about 0.2 % of the items.
        where:
        fault                                  | options                                                 | faults                                 | tries | attempts | executorConfig                                                  | timeout | inject                          || outcome | fragment
        'no fault'                             | SimOptions.DEFAULT                                      | FaultModel.NONE                        | 0     | 0        | null                                                            | 30      | null                            || 'DONE'  | ''
        '10% loss both ways'                   | SimOptions.DEFAULT                                      | FaultModel.loss(0.1, 11)               | 0     | 0        | null                                                            | 30      | null                            || 'DONE'  | ''
        '20% loss both ways'                   | SimOptions.DEFAULT                                      | FaultModel.loss(0.2, 12)               | 20    | 12       | null                                                            | 30      | null                            || 'DONE'  | ''
        'duplication and reordering'           | SimOptions.DEFAULT                                      | new FaultModel(0, 0.3, 0.02, 0.3, 13)  | 0     | 0        | null                                                            | 30      | null                            || 'DONE'  | ''
        'not ready at first, then ready'       | SimOptions.DEFAULT.withWarmup(8)                        | FaultModel.NONE                        | 0     | 0        | null                                                            | 30      | null                            || 'DONE'  | ''
        'never ready'                          | SimOptions.DEFAULT.withWarmup(600)                      | FaultModel.NONE                        | 0     | 0        | MissionExecutorConfig.DEFAULT.withPrepare(Duration.ofSeconds(10)) | 30    | null                            || 'ERROR' | 'vehicle 1 was not ready within 10 s: '
        'mode change refused'                  | new SimOptions(0, 14, true, true)                       | FaultModel.NONE                        | 0     | 0        | null                                                            | 30      | null                            || 'ERROR' | 'refused GUIDED'
        'vehicle lost during the mission'      | SimOptions.DEFAULT                                      | FaultModel.NONE                        | 0     | 0        | null                                                            | 5       | { SimVehicle v -> v.setSilent(true) }   || 'ERROR' | 'vehicle 1 lost'
        'mode switched by someone else'        | SimOptions.DEFAULT                                      | FaultModel.NONE                        | 0     | 0        | null                                                            | 30      | { SimVehicle v -> v.setMode(LOITER) }   || 'ERROR' | 'vehicle 1 left AUTO for LOITER during item '
    }

    def "a plane flies a waypoint mission and is DONE when it switches itself to RTL at the end"() {
        given:
        def fleet = h.fleet(1, VehicleKind.PLANE)
        SimVehicle plane = fleet.vehicle(1)

        when:
        def result = run('''
            tour = mission {
                name 'tour'
                takeOff location(40.444233, -7.375234, 870)
                goPos 40.4455, -7.375234, 870
                goPos 40.4455, -7.3737, 870
            }
            v = pick { timeout 10 }
            r = execute v: tour
            message "result: ${r}"
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('result: DONE')
        messages.contains('mission tour on vehicle 1: done')
        diffs(((Mission) engine.variable('tour')).items(plane.home()), plane.mission()) == []
        plane.modeName() == 'RTL'
    }

    def "jumpToItem flies a leg again the requested number of times"() {
        given:
        h.fleet(1)

        when:
        def result = run('''
            loop = mission {
                name 'loop'
                takeOff location(40.444233, -7.375234, 840)
                goPos 40.4444, -7.375234, 840
                goPos 40.4444, -7.37500, 840
                jumpToItem 2, 2
                landingPoint 40.4444, -7.37500, 820
            }
            v = pick { timeout 10 }
            r = execute v: loop
            message "result: ${r}"
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('result: DONE')
        messages.count('mission loop on vehicle 1: jump to item 2') == 2
        // item 3 (the leg's end, after which the jump is keyed) is reached once, then once per jump
        messages.count('mission loop on vehicle 1: item 3 of 4 reached') == 3
        messages.contains('mission loop on vehicle 1: done')
    }

    def "a mission ending in loiterPos never completes by itself; during 20 ends it DONE and the vehicle gets RTL"() {
        given:
        def fleet = h.fleet(1)
        SimVehicle vehicle = fleet.vehicle(1)

        when:
        def result = run('''
            stay = mission {
                name 'stay'
                takeOff location(40.444233, -7.375234, 840)
                loiterPos 40.4444, -7.375234, 840
            }
            v = pick { timeout 10 }
            execute v: during(20) run stay
        ''')

        then:
        result.outcome == ScriptResult.Outcome.COMPLETED
        // LOITER_UNLIM is never "reached" (ArduPilot's verify never ends it): only item 1 is reported
        messages.contains('mission stay on vehicle 1: item 1 of 2 reached')
        !messages.contains('mission stay on vehicle 1: item 2 of 2 reached')
        messages.contains('mission stay on vehicle 1: cut short: RTL')
        !messages.contains('mission stay on vehicle 1: done')
        h.eventually(5) { assert vehicle.modeName() == 'RTL' }
    }
}
