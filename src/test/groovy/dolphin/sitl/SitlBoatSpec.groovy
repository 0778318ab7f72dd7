package dolphin.sitl

import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.enums.MISSION_STATE
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
 * Dolphin against an ArduRover boat (`--model motorboat` with rover.parm and motorboat.parm, as
 * ArduPilot's autotest runs it): one boat (system id 31, instance 4, so its ports never clash with
 * the other specs' vehicles) on the sea off Comporta, started with the script. Runs only when
 * ARDUPILOT_SITL_ROVER_BIN names an ardurover binary; otherwise every feature is skipped.
 */
@Requires({ env.ARDUPILOT_SITL_ROVER_BIN })
@Timeout(value = 10, unit = TimeUnit.MINUTES)
class SitlBoatSpec extends Specification {

    static final Position HOME = Position.fromDegrees(38.43462, -8.86118, 0)

    @Shared
    @AutoCleanup
    SitlHarness sitl
    @Shared
    SitlReports reports

    def setupSpec() {
        sitl = new SitlHarness()
        reports = SitlReports.listeningTo(sitl.comms)
        sitl.start('ARDUPILOT_SITL_ROVER_BIN', 'ARDUPILOT_SITL_BOAT_DEFAULTS', 'rover.parm,motorboat.parm', 'motorboat', 31, 4, HOME)
    }

    def "started with the boat, as a user would: a USV, it waits for the boat to be ready, arms, drives its square in AUTO and is done when the last item is reached; the boat holds at home, still in AUTO, and the mission comes back as built"() {
        given:
        String script = 'src/test/resources/sitl/boat.dolphin'

        when: 'the script starts as soon as the SITL process does (setupSpec)'
        def r = sitl.run(new File(script).text, script, Duration.ofMinutes(8))
        MAVLinkNode node = sitl.comms.node('31')

        then: 'a boat with system id 31: ArduRover, announcing itself as a surface boat'
        node.family == VehicleFamily.ROVER
        node.type == 'USV'
        reports.heartbeatTypes[31] == [MAV_TYPE.MAV_TYPE_SURFACE_BOAT] as Set

        and: 'the square driven to its end, each of its four items reported reached'
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        inOrder(r.lines, 'mission square on vehicle 31: uploading 5 items', 'mission square on vehicle 31: upload verified*',
                'mission square on vehicle 31: armed', 'mission square on vehicle 31: started',
                'mission square on vehicle 31: item 4 of 4 reached', 'mission square on vehicle 31: done', 'square: DONE')
        reports.itemsReached[31] == [1, 2, 3, 4] as Set

        when: 'ArduRover ends the mission'
        SitlHarness.within(30) { assert node.state().missionState() == MISSION_STATE.MISSION_STATE_COMPLETE }

        then: 'the boat holds at home, armed, in AUTO (a boat loiters at the end of its mission), and the mission comes back as built'
        node.armed
        node.modeName == 'AUTO'
        node.position.distanceTo(HOME) < 5
        !MissionVerification.firstDifference(MissionLayer.missionOf(r.engine.variable('square')).items(node.home), sitl.download(node)).present
    }
}
