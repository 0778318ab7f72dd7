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
import spock.lang.Timeout

import static dolphin.testing.ScriptLines.inOrder

/**
 * Dolphin against ArduRover SITL (`--model rover`): one rover (system id 21, instance 3, so its ports
 * never clash with the copters' and the plane's), started with the script. Runs only when
 * ARDUPILOT_SITL_ROVER_BIN names an ardurover binary; otherwise every feature is skipped.
 */
@Requires({ env.ARDUPILOT_SITL_ROVER_BIN })
@Timeout(value = 10, unit = TimeUnit.MINUTES)
class SitlRoverSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    @Shared
    @AutoCleanup
    SitlHarness sitl

    def setupSpec() {
        sitl = new SitlHarness()
        sitl.start('ARDUPILOT_SITL_ROVER_BIN', 'ARDUPILOT_SITL_ROVER_DEFAULTS', 'rover.parm', 'rover', 21, 3, HOME)
    }

    def "started with the rover, as a user would: it waits for the rover to be ready, arms, drives its square in AUTO and is done when the mission is COMPLETE, holding at home; it comes back as built"() {
        given:
        String script = 'src/test/resources/sitl/rover.dolphin'

        when: 'the script starts as soon as the SITL process does (setupSpec)'
        def r = sitl.run(new File(script).text, script, Duration.ofMinutes(8))
        MAVLinkNode node = sitl.comms.node('21')

        then: 'a rover with system id 21'
        node.family == VehicleFamily.ROVER
        node.type == 'UGV'

        and:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        inOrder(r.lines, 'mission square on vehicle 21: uploading 5 items', 'mission square on vehicle 21: armed',
                'mission square on vehicle 21: started', 'mission square on vehicle 21: done', 'square: DONE')
        node.modeName == 'AUTO'
        node.position.distanceTo(HOME) < 5
        !MissionVerification.firstDifference(MissionLayer.missionOf(r.engine.variable('square')).items(node.home), sitl.download(node)).present
    }
}
