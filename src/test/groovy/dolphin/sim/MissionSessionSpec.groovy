package dolphin.sim

import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MISSION_STATE
import dolphin.core.SystemClock
import dolphin.mavlink.codec.CodecInteropSpec
import dolphin.mission.model.MissionItem
import spock.lang.Specification
import spock.lang.TempDir

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.TimeUnit

/**
 * A pymavlink ground station (harness/mission_session.py, the project's venv) uploads a mission to a
 * simulated copter the way MAVProxy does, downloads it back, starts it and sees it complete. Needs
 * the venv the build creates; without it the spec fails, it does not skip.
 */
class MissionSessionSpec extends Specification {

    static final Path PROJECT = Paths.get('').toAbsolutePath()
    static final Path PYTHON = PROJECT.resolve('.venv/bin/python')
    static final Path SCRIPT = PROJECT.resolve('harness/mission_session.py')
    static final int SESSION_SECONDS = 60
    static final int PROCESS_SECONDS = SESSION_SECONDS + 30

    @TempDir
    Path tmp

    /** pymavlink waits in wall time; the vehicle's 1 s re-request and 8 s upload timeout stay well above its replies. */
    final SystemClock clock = new SystemClock(5)
    SimFleet fleet
    Process process

    def cleanup() {
        fleet?.close()
        if (process?.alive) {
            process.destroyForcibly()
            process.waitFor(10, TimeUnit.SECONDS)
        }
    }

    def "pymavlink uploads a mission as MAVProxy does, downloads it back equal but for home, starts it and sees it complete"() {
        given:
        assert Files.isExecutable(PYTHON): "needs the project's venv at $PYTHON (bash harness/venv.sh)"
        Path portFile = tmp.resolve('port'), out = tmp.resolve('out'), err = tmp.resolve('err')
        def home = SimFleet.Config.of(1, VehicleKind.COPTER, new InetSocketAddress('127.0.0.1', 1)).home()
        process = new ProcessBuilder([PYTHON, SCRIPT, '--sysid', '1', '--port-file', portFile, '--deadline', SESSION_SECONDS,
                                      '--home', "${home.latitudeDegrees()},${home.longitudeDegrees()},${home.hae()}"]
                .collect { it.toString() }).directory(PROJECT.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File('/dev/null')))
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start()
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30)
        while (!Files.exists(portFile)) {
            assert process.alive: "mission_session.py exited before listening: ${Files.readString(err)}"
            assert System.nanoTime() < end: "mission_session.py did not listen within 30 s: ${Files.readString(err)}"
            process.waitFor(20, TimeUnit.MILLISECONDS)
        }
        int port = Files.readString(portFile).trim() as int

        when:
        fleet = new SimFleet(SimFleet.Config.of(1, VehicleKind.COPTER, new InetSocketAddress('127.0.0.1', port)), clock)
        fleet.start()
        def sim = fleet.vehicle(1)
        boolean exited = process.waitFor(PROCESS_SECONDS, TimeUnit.SECONDS)
        assert exited: "mission_session.py did not finish within $PROCESS_SECONDS s: ${Files.readString(err)}"
        assert process.exitValue() == 0: Files.readString(err)
        Map report = CodecInteropSpec.Json.parse(Files.readString(out).trim()) as Map

        then: 'no step timed out'
        report.errors == []

        and: 'the upload: every item asked for with MISSION_REQUEST (id 40), in order, then ACCEPTED'
        report.upload.requests == (0..5).collect { ['MISSION_REQUEST', it] }
        report.upload.ack == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        report.flight.texts.contains('Flight plan received')

        and: 'the download equals the upload but for seq 0, which is home in MAV_FRAME_GLOBAL'
        report.download.count == 6
        report.download.equal_except_home
        report.download.differences == []
        with(report.download.items[0] as Map) {
            frame == MAV_FRAME.MAV_FRAME_GLOBAL
            command == MAV_CMD.MAV_CMD_NAV_WAYPOINT
            x == MissionItem.degE7(home.latitudeDegrees())
            y == MissionItem.degE7(home.longitudeDegrees())
            Math.abs((z as double) - home.hae()) < 0.01
        }

        and: 'the flight: GUIDED, arm and MISSION_START accepted; disarmed in AUTO after the landing'
        report.flight.commands == [guided: MAV_RESULT.MAV_RESULT_ACCEPTED, arm: MAV_RESULT.MAV_RESULT_ACCEPTED,
                                   mission_start: MAV_RESULT.MAV_RESULT_ACCEPTED]
        (report.flight.current as List).any { it == [1, 5, MISSION_STATE.MISSION_STATE_ACTIVE] }

        and: 'as ArduCopter SITL ends on NAV_LAND: never reached, no COMPLETE, the mission back at item 1, ACTIVE'
        (report.flight.reached as List).last() == 4
        !(report.flight.current as List).any { it[2] == MISSION_STATE.MISSION_STATE_COMPLETE }
        (report.flight.current as List).last() == [1, 5, MISSION_STATE.MISSION_STATE_ACTIVE]
        !report.flight.last_heartbeat_armed
        report.flight.last_custom_mode == COPTER_MODE.COPTER_MODE_AUTO
        !sim.armed()
        sim.mission().size() == 6
    }
}
