package dolphin.sitl

import dolphin.testing.MissionLayer
import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import dolphin.mission.transfer.MissionVerification
import java.time.Duration
import java.util.concurrent.TimeUnit
import spock.lang.AutoCleanup
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Stepwise
import spock.lang.Timeout

import static dolphin.testing.ScriptLines.inOrder

/**
 * Dolphin against ArduPlane SITL: one plane (system id 11, instance 2, so its ports never clash with
 * SitlSpec's copters), started with the script. Runs only when ARDUPILOT_SITL_PLANE_BIN names an
 * arduplane binary; otherwise every feature is skipped.
 */
@Requires({ env.ARDUPILOT_SITL_PLANE_BIN })
@Stepwise
@Timeout(value = 15, unit = TimeUnit.MINUTES)
class SitlPlaneSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    @Shared
    @AutoCleanup
    SitlHarness sitl
    @Shared
    MAVLinkNode node

    def setupSpec() {
        sitl = new SitlHarness()
        sitl.start('ARDUPILOT_SITL_PLANE_BIN', 'ARDUPILOT_SITL_PLANE_DEFAULTS', 'plane.parm', 'plane', 11, 2, HOME)
    }

    def "started with the plane, as a user would: it waits for the plane to be ready, takes off, flies two waypoints and a loiter turn back to home, and the mission ends as ArduPlane ends it (its own RTL); it comes back as built"() {
        given:
        String script = 'src/test/resources/sitl/plane.dolphin'

        when: 'the script starts as soon as the SITL process does (setupSpec)'
        def r = sitl.run(new File(script).text, script, Duration.ofMinutes(10))
        node = sitl.comms.node('11')

        then: 'a plane with system id 11, waited for until it was ready'
        node.family == VehicleFamily.PLANE
        node.home.distanceTo(HOME) < 20
        r.lines.any { it.startsWith('waiting for vehicle 11: ') }

        and:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        inOrder(r.lines, 'mission circuit on vehicle 11: vehicle ready after *', 'mission circuit on vehicle 11: uploading 6 items',
                'mission circuit on vehicle 11: armed', 'mission circuit on vehicle 11: started', 'mission circuit on vehicle 11: done',
                'circuit: DONE')
        node.modeName == 'RTL'
        !MissionVerification.firstDifference(MissionLayer.missionOf(r.engine.variable('circuit')).items(node.home), sitl.download(node)).present
    }
}
