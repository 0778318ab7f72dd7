package dolphin.mavlink

import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_TYPE
import dolphin.core.SystemClock
import dolphin.mavlink.codec.CodecInteropSpec
import dolphin.mavlink.codec.Frame
import dolphin.sim.SimFleet
import dolphin.sim.SimOptions
import dolphin.sim.SimVehicle
import dolphin.sim.VehicleKind
import spock.lang.Specification
import spock.lang.TempDir

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.time.Instant
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger

/**
 * An independent peer (design §9): a pymavlink ground station (harness/gcs_session.py, run with the
 * project's venv) connects to our simulated vehicles, sees their heartbeats, requests streams, arms
 * and changes mode; and pymavlink reads the .tlog our ground station writes. Needs the venv the
 * build creates (harness/venv.sh); without it the spec fails, it does not skip.
 */
class PymavlinkGroundStationSpec extends Specification {

    static final Path PROJECT = Paths.get('').toAbsolutePath()
    static final Path PYTHON = PROJECT.resolve('.venv/bin/python')
    static final Path SCRIPT = PROJECT.resolve('harness/gcs_session.py')
    /** The session's own deadline (every wait in the script is bounded by it) ... */
    static final int SESSION_SECONDS = 60
    /** ... and ours for the process, which includes Python's start-up. */
    static final int PROCESS_SECONDS = SESSION_SECONDS + 30
    static final long INTERVAL_US = 200_000

    @TempDir
    Path tmp

    /** pymavlink uses wall time, so the simulated vehicles run in real time. */
    final SystemClock clock = new SystemClock(1)
    final List<SimFleet> fleets = []
    final List<Process> processes = []

    def setupSpec() {
        if (!Files.isExecutable(PYTHON)) {
            throw new IllegalStateException("PymavlinkGroundStationSpec needs the project's Python venv with the pinned pymavlink " +
                    "at $PYTHON; the Maven build creates it (harness/generate-bindings.sh runs harness/venv.sh), or run " +
                    "'bash harness/venv.sh' in $PROJECT")
        }
    }

    def cleanup() {
        fleets.each { it.close() }
        processes.findAll { it.alive }.each {
            it.destroyForcibly()
            it.waitFor(10, TimeUnit.SECONDS)
        }
    }

    def "a pymavlink ground station sees the copters' heartbeats, gets the streams it asks for, arms them and sets GUIDED"() {
        given: 'pymavlink listening on an ephemeral UDP port'
        Path portFile = tmp.resolve('port')
        def gcs = start('session', ['session', '--sysids', '1,2,3', '--port-file', portFile, '--deadline', SESSION_SECONDS,
                                    '--interval-us', INTERVAL_US])
        int port = awaitPort(gcs, portFile)

        when: 'two copters ready to arm (sysids 1, 2) and one still warming up (3) send to it, each from its own port'
        def ready = fleet(port, 1, 2, SimOptions.DEFAULT.withWarmup(0))
        def warming = fleet(port, 3, 1, SimOptions.DEFAULT.withWarmup(600))
        List<SimVehicle> sims = ready.vehicles() + warming.vehicles()
        Map<Integer, Integer> ports = [1: ready.port(1), 2: ready.port(2), 3: warming.port(3)]
        List<Map> streamsAtStart = sims.collect { it.streams() }
        Map report = finish(gcs)
        Map<String, Map> v = report.vehicles as Map<String, Map>

        then: "the session finished every step, and no frame was missing from any vehicle's sequence numbers"
        report.errors == []
        report.mav_loss == 0
        v.keySet() == ['1', '2', '3'] as Set

        and: 'heartbeats from every system: ArduPilot copters in STABILIZE, MAVLink 2, each from its own socket'
        v.every { id, x -> x.heartbeat.type == MAV_TYPE.MAV_TYPE_QUADROTOR && x.heartbeat.autopilot == MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA }
        v.every { id, x -> x.heartbeat.custom_mode == COPTER_MODE.COPTER_MODE_STABILIZE && x.frame_magic == 0xFD }
        v.collectEntries { id, x -> [(id as int): x.address[1]] } == ports
        ports.values().toSet().size() == 3

        and: 'no stream before it was asked for: the copters streamed nothing, and pymavlink heard only heartbeats (two or more each) until it asked'
        streamsAtStart.every { it.isEmpty() }
        v.every { id, x -> x.before_request.keySet() == ['HEARTBEAT'] as Set && x.before_request.HEARTBEAT >= 2 }

        and: 'SET_MESSAGE_INTERVAL accepted, then GLOBAL_POSITION_INT and SYS_STATUS arrived, each after its own request'
        v.every { id, x ->
            ['GLOBAL_POSITION_INT', 'SYS_STATUS'].every { name ->
                Map s = x.streams[name] as Map
                s.result == MAV_RESULT.MAV_RESULT_ACCEPTED && s.count > 0 && s.first_received > s.sent
            }
        }
        sims.every { it.streams() == [(1): INTERVAL_US * 1000, (33): INTERVAL_US * 1000] }

        and: "the positions pymavlink decoded are the simulator's; the copter warming up sends zeros, as ArduPilot without a position estimate"
        ready.vehicles().every { sim ->
            Map p = v[sim.sysid() as String].position as Map
            p.lat == Math.round(sim.position().latitudeDegrees() * 1e7) && p.lon == Math.round(sim.position().longitudeDegrees() * 1e7)
        }
        (v['3'].position as Map).with { it.lat == 0 && it.lon == 0 }

        and: 'arming: accepted by the ready copters, saying so as ArduCopter does, refused with the PreArm text by the one warming up; ACKs addressed to pymavlink (255)'
        v['1'].arm.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        v['2'].arm.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        v['1'].arm.statustext*.text == ['Arming motors'] && v['2'].arm.statustext*.text == ['Arming motors']
        v['3'].arm.result == MAV_RESULT.MAV_RESULT_FAILED
        v['3'].arm.statustext*.text == ['PreArm: Need Position Estimate']
        v.every { id, x -> x.arm.target_system == 255 }

        and: 'GUIDED accepted and shown by a heartbeat received after the ACK, armed as the arm result says; pymavlink names it GUIDED'
        v.every { id, x -> x.mode.result == MAV_RESULT.MAV_RESULT_ACCEPTED && x.mode.guided_heartbeat.custom_mode == COPTER_MODE.COPTER_MODE_GUIDED }
        v.collectEntries { id, x -> [(id): x.mode.guided_heartbeat.armed] } == ['1': true, '2': true, '3': false]
        v.every { id, x -> x.mode.pymavlink_flightmode == 'GUIDED' }

        and: "the simulator's own state agrees, and each vehicle handled exactly the COMMAND_LONGs sent to its address"
        sims.collectEntries { [(it.sysid()): it.armed()] } == [1: true, 2: true, 3: false]
        sims.every { it.modeName() == 'GUIDED' }
        sims.collectEntries { [(it.sysid()): it.commandsHandled()] } == v.collectEntries { id, x ->
            [(id as int): x.streams.values().sum { it.attempts } + x.arm.attempts + x.mode.attempts]
        }
    }

    def "pymavlink reads our ground station's tlog: every frame, heartbeats from the vehicles and from us, wall-clock times"() {
        given:
        Path tlog = tmp.resolve('gcs.tlog')
        double startedAt = unixSeconds()
        def h = new FleetHarness(MAVLinkConfig.of('udpin:127.0.0.1:0').withTlog(tlog))

        def heartbeatsSent = new AtomicInteger()
        h.comms.addObserver { boolean incoming, link, Frame f ->
            if (!incoming && f.msgid() == 0) {
                heartbeatsSent.incrementAndGet()
            }
        }

        when: 'our ground station talks to two copters until their positions arrive and it has sent them heartbeats, then closes'
        h.fleet(2)
        h.eventually(20) {
            assert h.comms.nodes().size() == 2 && h.comms.nodes().every { it.state().position() != null }
            assert heartbeatsSent.get() >= 4
        }
        h.close()
        double closedAt = unixSeconds()
        long frames = h.comms.framesIn() + h.comms.framesOut()
        Map log = run('tlog', ['tlog', tlog])
        Map<String, Map<String, Integer>> bySysid = log.by_sysid as Map

        then: 'pymavlink parses every frame we logged, in and out, and nothing else'
        log.reader == 'mavmmaplog'
        log.bad_data == 0
        log.seq_gaps == 0
        log.frames == frames
        log.indexed == frames
        bySysid.values().sum { it.values().sum() } == frames

        and: 'heartbeats and positions from the vehicles; heartbeats and stream requests from our ground station'
        bySysid.keySet() == ['1', '2', MAVLinkConfig.DEFAULT_SYSID as String] as Set
        ['1', '2'].every { bySysid[it].HEARTBEAT > 0 && bySysid[it].GLOBAL_POSITION_INT > 0 && bySysid[it].COMMAND_ACK > 0 }
        bySysid[MAVLinkConfig.DEFAULT_SYSID as String].HEARTBEAT == heartbeatsSent.get()
        bySysid[MAVLinkConfig.DEFAULT_SYSID as String].COMMAND_LONG > 0

        and: 'timestamps are Unix times within the run, never going back'
        (log.first_timestamp as double) >= startedAt - 0.001
        (log.last_timestamp as double) <= closedAt + 0.001
        (log.first_timestamp as double) <= (log.last_timestamp as double)
        log.backwards == 0

        cleanup:
        h?.close()
    }

    // ---- helpers -------------------------------------------------------------------------------

    SimFleet fleet(int port, int firstSysid, int count, SimOptions options) {
        def config = SimFleet.Config.of(count, VehicleKind.COPTER, new InetSocketAddress('127.0.0.1', port))
                .withFirstSysid(firstSysid).withOptions(options)
        def f = new SimFleet(config, clock)
        fleets << f
        f.start()
        f
    }

    static double unixSeconds() {
        Instant now = Instant.now()
        now.epochSecond + now.nano / 1e9
    }

    /** A run of the harness, its output going to files named after it in the temp dir. */
    static final class Harness {
        final String name
        final Process process
        final Path out
        final Path err

        Harness(String name, Process process, Path out, Path err) {
            this.name = name
            this.process = process
            this.out = out
            this.err = err
        }

        String stderr() {
            Files.exists(err) ? Files.readString(err) : ''
        }
    }

    Harness start(String name, List<?> args) {
        List<String> command = ([PYTHON, SCRIPT] + args).collect { it.toString() }
        Path out = tmp.resolve("${name}.out"), err = tmp.resolve("${name}.err")
        Process p = new ProcessBuilder(command).directory(PROJECT.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File('/dev/null')))
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start()
        processes << p
        new Harness(name, p, out, err)
    }

    /** Waits (bounded) for the harness to write the port it listens on. */
    static int awaitPort(Harness h, Path portFile) {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30)
        while (!Files.exists(portFile)) {
            if (!h.process.alive) {
                throw new AssertionError("harness ${h.name} exited (${h.process.exitValue()}) before listening: ${h.stderr()}")
            }
            if (System.nanoTime() > end) {
                throw new AssertionError("harness ${h.name} did not write $portFile within 30 s: ${h.stderr()}")
            }
            h.process.waitFor(20, TimeUnit.MILLISECONDS)
        }
        Files.readString(portFile).trim() as int
    }

    /** Waits (bounded) for the harness to exit and parses the JSON document it printed. */
    static Map finish(Harness h) {
        Process p = h.process
        if (!p.waitFor(PROCESS_SECONDS, TimeUnit.SECONDS)) {
            p.destroyForcibly()
            p.waitFor(10, TimeUnit.SECONDS)
            throw new AssertionError("harness ${h.name} did not finish within $PROCESS_SECONDS s: ${h.stderr()}")
        }
        String text = Files.readString(h.out).trim()
        if (p.exitValue() != 0 || !text) {
            throw new AssertionError("harness ${h.name} exited with ${p.exitValue()}: ${h.stderr()}")
        }
        CodecInteropSpec.Json.parse(text) as Map
    }

    Map run(String name, List<?> args) {
        finish(start(name, args))
    }
}
