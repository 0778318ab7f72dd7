package dolphin.sitl

import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import java.time.Duration
import java.util.concurrent.TimeUnit
import spock.lang.AutoCleanup
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.testing.ScriptLines.inOrder

/**
 * Dolphin against ArduCopter's traditional helicopter: the `arducopter-heli` SITL binary (its own
 * build target, `./waf heli`), model `heli`, ArduPilot's copter-heli.parm (or
 * ARDUPILOT_SITL_HELI_DEFAULTS), system id 41, instance 7 (docs/vtol.md, "Helicopters"). Runs only
 * when ARDUPILOT_SITL_HELI_BIN names the binary.
 */
@Requires({ env.ARDUPILOT_SITL_HELI_BIN })
@Timeout(value = 15, unit = TimeUnit.MINUTES)
class SitlHeliSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    @Shared
    @AutoCleanup
    SitlHarness sitl

    def setupSpec() {
        sitl = new SitlHarness()
        sitl.start('ARDUPILOT_SITL_HELI_BIN', 'ARDUPILOT_SITL_HELI_DEFAULTS', 'copter-heli.parm', 'heli', 41, 7, HOME)
    }

    def "the first-flight example on a helicopter, started with it: its motor interlock off to arm, on to run its rotor up before AUTO, off again once landed"() {
        given:
        String script = 'dsl-examples/first-flight.dolphin'

        when:
        def r = sitl.run(new File(script).text, script, Duration.ofMinutes(10))
        MAVLinkNode node = sitl.comms.node('41')

        then:
        node.family == VehicleFamily.HELI
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        inOrder(r.lines, 'mission first flight on vehicle 41: armed', 'mission first flight on vehicle 41: started',
                'mission first flight on vehicle 41: item 3 of 4 reached',
                'mission first flight on vehicle 41: motor interlock off (DO_AUX_FUNCTION 32 low)',
                'mission first flight on vehicle 41: done')
        !node.armed
        node.position.distanceTo(HOME.displace(50, 50, 0)) < 15
    }
}
