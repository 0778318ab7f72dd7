package dolphin.sitl

import dolphin.core.Position
import dolphin.dsl.ScriptResult
import java.nio.file.Path
import java.time.Duration
import java.util.concurrent.TimeUnit
import spock.lang.AutoCleanup
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.testing.ScriptLines.inOrder
import static dolphin.testing.ScriptLines.parsePosition

/**
 * dsl-examples/fire-watch.dolphin on three ArduCopter SITL (docs/sensors.md): copters 1 and 2 run
 * src/test/resources/lua/smoke-plume.lua (SCR_ENABLE 1), which sends SMOKE from their own position,
 * copter 3 has a servo camera (CAM1_TYPE 1), which it announces in CAMERA_INFORMATION when asked.
 * Runs only when ARDUPILOT_SITL_BIN names an arducopter binary.
 */
@Requires({ env.ARDUPILOT_SITL_BIN })
@Timeout(value = 15, unit = TimeUnit.MINUTES)
class SitlSensorSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    /** smoke-plume.lua's plume: SMOKE is above 0 within 60 m of it. */
    static final Position PLUME = Position.fromDegrees(40.4461, -7.3752, 0)

    @Shared
    @AutoCleanup
    SitlHarness sitl

    def setupSpec() {
        sitl = new SitlHarness()
        Path lua = Path.of(SitlSensorSpec.getResource('/lua/smoke-plume.lua').toURI())
        [1, 2].each { n -> sitl.start('ARDUPILOT_SITL_BIN', 'ARDUPILOT_SITL_DEFAULTS', 'copter.parm', 'quad', n, n + 9, HOME, ['SCR_ENABLE 1'], [lua]) }
        sitl.start('ARDUPILOT_SITL_BIN', 'ARDUPILOT_SITL_DEFAULTS', 'copter.parm', 'quad', 3, 12, HOME, ['CAM1_TYPE 1'])
    }

    def "fire watch: a scout reads the Lua script's plume, the copter with a camera is picked and flies over it, all land"() {
        when:
        def r = sitl.run(new File('dsl-examples/fire-watch.dolphin').text, 'dsl-examples/fire-watch.dolphin', Duration.ofMinutes(12))
        List<String> lines = r.lines
        String smoke = lines.find { it ==~ /smoke [\d.]+ read by vehicle \{ [12] \} at .*/ }
        String over = lines.find { it.startsWith('vehicle { 3 } over the fire at ') }

        then:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        smoke && over
        horizontal(parsePosition(smoke)) < 60
        horizontal(parsePosition(over)) < 60
        inOrder(lines, 'task watch the fire started on vehicle 3', 'task watch the fire completed on vehicle 3')
        inOrder(lines, 'task back home completed on vehicle 1')
        inOrder(lines, 'task back home completed on vehicle 2')
        lines.contains('fire watch: DONE')
    }

    static double horizontal(Position p) {
        p.distanceTo(Position.fromDegrees(PLUME.latitudeDegrees(), PLUME.longitudeDegrees(), p.hae()))
    }
}
