package dolphin.sitl

import dolphin.testing.MissionLayer
import dolphin.core.Position
import dolphin.core.SystemClock
import dolphin.core.TaskEvent
import dolphin.dsl.Engine
import dolphin.dsl.EngineListener
import dolphin.dsl.ScriptResult
import dolphin.mavlink.CommandResult
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.MAVLinkNode
import dolphin.platform.MAVLinkPlatform
import dolphin.mission.model.MissionItem
import dolphin.mission.transfer.TransferResult
import java.time.Duration
import java.util.concurrent.TimeUnit
import spock.util.concurrent.PollingConditions

/**
 * Our ground station (MAVLinkCommunications on udpin 127.0.0.1, a private port, real time, as
 * `dolphin run` has it) and the SITL processes that send to it. Configured from the environment:
 * ARDUPILOT_SITL_BIN (arducopter), ARDUPILOT_SITL_PLANE_BIN (arduplane), ARDUPILOT_SITL_ROVER_BIN
 * (ardurover, for rovers and boats), ARDUPILOT_SITL_SUB_BIN (ardusub), ARDUPILOT_SITL_DEFAULTS,
 * ARDUPILOT_SITL_PLANE_DEFAULTS, ARDUPILOT_SITL_ROVER_DEFAULTS, ARDUPILOT_SITL_BOAT_DEFAULTS and
 * ARDUPILOT_SITL_SUB_DEFAULTS (their parameter files, comma-separated; by default ArduPilot's
 * copter.parm, plane.parm, rover.parm, rover.parm with motorboat.parm, or sub.parm, found in
 * Tools/autotest from a binary in build/sitl/bin), ARDUPILOT_SITL_SPEEDUP (SITL's --speedup,
 * default 1); for PX4, PX4_SITL_BIN (build/px4_sitl_default/bin/px4) and PX4_SITL_SPEEDUP (its
 * PX4_SIM_SPEED_FACTOR, default 1); SITL_TLOG_DIR for telemetry logs ({@link #tlogged}). Close it to stop
 * every process.
 */
class SitlHarness implements AutoCloseable {

    static final double SPEEDUP = (System.getenv('ARDUPILOT_SITL_SPEEDUP') ?: '1') as double
    static final double PX4_SPEEDUP = (System.getenv('PX4_SITL_SPEEDUP') ?: '1') as double

    final MAVLinkCommunications comms
    final List<AutoCloseable> vehicles = []
    /** The program's messages and the platform tasks' events, as `dolphin run` prints them (without times). */
    final List<String> lines = Collections.synchronizedList([])

    SitlHarness() {
        this('udpin:127.0.0.1:0')
    }

    /** A ground station on these links: PX4 SITL's are udpout to each vehicle ({@link #px4Links}). */
    SitlHarness(String... links) {
        comms = new MAVLinkCommunications(tlogged(MAVLinkConfig.of(links)), SystemClock.REAL)
        comms.start()
    }

    /**
     * With SITL_TLOG_DIR set, the ground station keeps a telemetry log there, named after the spec and the
     * time it began (SitlPx4Spec-20261128T130000.123.tlog): what the vehicles said when a feature failed.
     */
    static MAVLinkConfig tlogged(MAVLinkConfig config) {
        String dir = System.getenv('SITL_TLOG_DIR')
        if (!dir) {
            return config
        }
        String spec = StackWalker.getInstance().walk { frames ->
            frames.map { it.className.tokenize('.$').find { it.endsWith('Spec') } }.filter { it != null }.findFirst().orElse('Sitl')
        }
        String time = java.time.LocalDateTime.now().format(java.time.format.DateTimeFormatter.ofPattern("yyyyMMdd'T'HHmmss.SSS"))
        def file = java.nio.file.Path.of(dir).resolve("${spec}-${time}.tlog")
        java.nio.file.Files.createDirectories(file.parent)
        config.withTlog(file)
    }

    /** The links to talk to PX4 SITL instances 0 to {@code count} - 1. */
    static String[] px4Links(int count) {
        (0..<count).collect { "udpout:127.0.0.1:${Px4SitlVehicle.GCS_PORT + it}".toString() } as String[]
    }

    /**
     * Starts PX4 SITL instance {@code instance} (system id instance + 1) of the SIH model, e.g. quadx,
     * standard_vtol, with these parameters and its flight log off (SDLOG_MODE -1): PX4 SITL logs from
     * arming, and two instances starting their logs at once on a busy machine lost their baro and compass.
     * The binary is named by the environment variable {@code binaryVariable}.
     */
    Px4SitlVehicle startPx4(String model, int instance, Position home, Map<String, Object> params = [:],
                            String binaryVariable = 'PX4_SITL_BIN') {
        String binary = new File(System.getenv(binaryVariable)).absolutePath
        assert new File(binary).canExecute(): "${binaryVariable}=${binary} is not an executable file"
        def v = new Px4SitlVehicle(binary, model, instance, home, PX4_SPEEDUP, [SDLOG_MODE: -1] + params)
        vehicles << v
        v
    }

    /**
     * Starts a vehicle: binary from the environment variable {@code binaryVariable}, parameter files
     * from {@code defaultsVariable} or {@code parmFiles} (comma-separated, later ones overriding, as
     * ArduPilot's autotest layers motorboat.parm over rover.parm) next to ArduPilot's build.
     */
    SitlVehicle start(String binaryVariable, String defaultsVariable, String parmFiles, String model, int sysid, int instance, Position home,
                      List<String> params = [], List<java.nio.file.Path> scripts = []) {
        String binary = new File(System.getenv(binaryVariable)).absolutePath
        assert new File(binary).canExecute(): "${binaryVariable}=${binary} is not an executable file"
        def v = new SitlVehicle(binary, model, sysid, instance, home, defaults(binary, defaultsVariable, parmFiles), SPEEDUP,
                comms.links()[0].localPort(), params, scripts)
        vehicles << v
        v
    }

    /**
     * The parameter files, comma-separated as SITL's --defaults takes them: named by the variable, else
     * ArduPilot's own, from build/sitl/bin/BINARY up to the source tree; null when one is not found.
     */
    static String defaults(String binary, String variable, String parmFiles) {
        String named = System.getenv(variable)
        if (named) {
            List<File> files = named.split(',').collect { new File(it) }
            files.each { assert it.isFile(): "${variable}=${named}: ${it} is not a file" }
            return files*.absolutePath.join(',')
        }
        def guess = new File(binary).parentFile?.parentFile?.parentFile?.parentFile
        // copter.parm, rover.parm, motorboat.parm and sub.parm are in default_params, plane.parm among the models
        List<File> found = parmFiles.split(',').collect { parmFile ->
            guess == null ? null : ['default_params', 'models'].collect { new File(guess, "Tools/autotest/${it}/${parmFile}") }.find { it.isFile() }
        }
        found.contains(null) ? null : found*.absolutePath.join(',')
    }

    /**
     * Waits until {@code count} vehicles are heard, then {@code seconds} more (real time). PX4's SIH at a
     * speed factor above 1 on a busy machine can lose its baro and compass in its first seconds ("Preflight
     * Fail: No valid data from Baro 0") after saying it may arm, and lands at once when armed then: a SITL
     * start-up artefact, which the PX4 specs let pass before their first script.
     */
    void settle(int count, double seconds) {
        within(60) { assert comms.nodes().size() == count }
        Thread.sleep(Math.round(seconds * 1000))
    }

    /** Runs a script with a new Engine on this ground station; its result, or a failure after {@code deadline}. */
    Map run(String source, String name, Duration deadline) {
        lines.clear()
        def engine = new Engine(new MAVLinkPlatform(comms), SystemClock.REAL)
        engine.addListener(new EngineListener() {
            @Override
            void message(String text) { lines << text }

            @Override
            void taskEvent(TaskEvent event) {
                if (event.platformTask) {
                    lines << "task ${event.task().id} ${event.kind().name().toLowerCase(Locale.ROOT)} on vehicle ${event.vehicles().join(',')}".toString()
                }
            }
        })
        try {
            def run = engine.run(source, name)
            ScriptResult result = run.await(deadline)
            if (result == null) {
                run.stop()
                assert false: "${name} did not end within ${deadline}; lines so far:\n${lines.join('\n')}"
            }
            [result: result, engine: engine, lines: List.copyOf(lines)]
        } finally {
            engine.close()
        }
    }

    /**
     * Sets each vehicle's battery to {@code percent} (MAV_CMD_BATTERY_RESET) once it flies its
     * mission's second item, after the take-off, until {@code vehicles} of them are set; their answers
     * go in {@code resets}, by system id. Interrupt the thread when the feature is over.
     */
    Thread setBatteriesOnSurvey(Map<Integer, CommandResult> resets, int vehicles, float percent) {
        Thread.start('battery reset') {
            try {
                while (resets.size() < vehicles) {
                    comms.nodes().findAll { !resets.containsKey(it.mavLinkId) && it.armed && it.state().missionSeq() >= 2 }.each {
                        // param1: battery mask (the first battery, the one SYS_STATUS reports), param2: percentage
                        resets[it.mavLinkId] = command(it, com.MAVLink.enums.MAV_CMD.MAV_CMD_BATTERY_RESET, 1, percent, 0, 0, 0, 0, 0)
                    }
                    Thread.sleep(100)
                }
            } catch (InterruptedException ignored) {
                // the feature is over: its cleanup ends the watch
            }
        }
    }

    /** Sends a COMMAND_LONG and waits for its COMMAND_ACK (the sender retries on its own). */
    CommandResult command(MAVLinkNode node, int command, float... params) {
        comms.command(node, command, params).get(30, TimeUnit.SECONDS)
    }

    TransferResult upload(MAVLinkNode node, List<MissionItem> items) {
        MissionLayer.uploads(node).upload(items).get(120, TimeUnit.SECONDS)
    }

    List<MissionItem> download(MAVLinkNode node) {
        MissionLayer.downloads(node).download().get(120, TimeUnit.SECONDS).orThrow()
    }

    /** Waits up to {@code seconds} (real time) for the condition, a closure with assertions. */
    static void within(double seconds, Closure condition) {
        new PollingConditions(timeout: seconds, delay: 0.2).eventually(condition)
    }

    @Override
    void close() {
        vehicles.each { it.close() }
        comms.close()
    }
}
