package dolphin.sitl

import com.MAVLink.enums.MAV_VTOL_STATE
import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.Autopilot
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import java.time.Duration
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.TimeUnit
import spock.lang.AutoCleanup
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.testing.ScriptLines.inOrder

/**
 * Dolphin against a PX4 standard VTOL: PX4 SITL with SIH's `standard_vtol` model, instance 2
 * (system id 3), at the examples' home, the script started 10 s after it is heard ({@link SitlHarness#settle};
 * docs/px4.md). Runs only when
 * PX4_SITL_BIN names the px4 binary.
 */
@Requires({ env.PX4_SITL_BIN })
@Timeout(value = 20, unit = TimeUnit.MINUTES)
class SitlPx4VtolSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    @Shared
    @AutoCleanup
    SitlHarness sitl

    def setupSpec() {
        sitl = new SitlHarness(SitlHarness.px4Links(3)[2])
        sitl.startPx4('standard_vtol', 2, HOME)
        sitl.settle(1, 10)
    }

    def "the VTOL mapping example: a vertical take-off, the transition, the survey as a plane, the back-transition and a vertical landing at home"() {
        given: 'the VTOL states the vehicle goes through, as EXTENDED_SYS_STATE says them, sampled every 100 ms'
        Set<Integer> states = ConcurrentHashMap.newKeySet()
        Thread watcher = Thread.start('vtol states') {
            try {
                while (true) {
                    sitl.comms.nodes().each { states << it.state().vtolState() }
                    Thread.sleep(100)
                }
            } catch (InterruptedException ignored) {
                // the feature is over
            }
        }
        String script = 'dsl-examples/vtol-mapping.dolphin'

        when:
        def r = sitl.run(new File(script).text, script, Duration.ofMinutes(15))
        MAVLinkNode node = sitl.comms.node('3')

        then:
        node.state().autopilot() == Autopilot.PX4
        node.family == VehicleFamily.VTOL
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        inOrder(r.lines, 'mission vtol mapping on vehicle 3: upload verified*', 'mission vtol mapping on vehicle 3: armed',
                'mission vtol mapping on vehicle 3: started', 'mission vtol mapping on vehicle 3: done', 'mapping: DONE')
        // the back-transition lasts a few tenths of a second at a speed factor of 4, too short to be sampled for sure
        states.containsAll([MAV_VTOL_STATE.MAV_VTOL_STATE_MC, MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_FW, MAV_VTOL_STATE.MAV_VTOL_STATE_FW])
        node.position.distanceTo(HOME) < 15
        !node.armed

        cleanup:
        watcher?.interrupt()
    }
}
