package dolphin.sitl

import com.MAVLink.enums.MAV_CMD
import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.CommandResult
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import java.time.Duration
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.TimeUnit
import spock.lang.AutoCleanup
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Stepwise
import spock.lang.Timeout

import static dolphin.testing.ScriptLines.after
import static dolphin.testing.ScriptLines.inOrder
import static dolphin.testing.ScriptLines.parsePosition
import static dolphin.testing.ScriptLines.vehicleOf

/**
 * Dolphin against two QuadPlanes: ArduPlane SITL's `quadplane` model with ArduPilot's quadplane.parm
 * (or ARDUPILOT_SITL_VTOL_DEFAULTS) and a battery monitor, system ids 31 and 32, instances 5 and 6, started with the first
 * script (docs/vtol.md). Runs only when ARDUPILOT_SITL_PLANE_BIN names an arduplane binary.
 */
@Requires({ env.ARDUPILOT_SITL_PLANE_BIN })
@Stepwise
@Timeout(value = 25, unit = TimeUnit.MINUTES)
class SitlVtolSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final Duration RUN_DEADLINE = Duration.ofMinutes(15)
    /** The survey is cut below 70 %: the battery is set just above it once the survey has begun. */
    static final float CUT_BATTERY = 72

    @Shared
    @AutoCleanup
    SitlHarness sitl

    def setupSpec() {
        sitl = new SitlHarness()
        [31, 32].eachWithIndex { sysid, i ->
            // quadplane.parm has no battery monitor, which the scenario's battery() reads: SITL's simulated one
            sitl.start('ARDUPILOT_SITL_PLANE_BIN', 'ARDUPILOT_SITL_VTOL_DEFAULTS', 'quadplane.parm', 'quadplane', sysid, 5 + i,
                    HOME.displace(0, 10 * i, 0), ['BATT_MONITOR 4'])
        }
    }

    def "the report's two-vehicle scenario flown by two QuadPlanes: vertical take-offs, surveys cut below 70 % by QRTL, return missions landing vertically at home"() {
        given: 'a watcher that sets each battery to 72 % once its vehicle flies the survey'
        Map<Integer, CommandResult> resets = new ConcurrentHashMap<>()
        Thread watcher = sitl.setBatteriesOnSurvey(resets, 2, CUT_BATTERY)

        when: 'the script starts as soon as the SITL processes do'
        def r = sitl.run(new File('dsl-examples/two-drones-survey.dolphin').text, 'dsl-examples/two-drones-survey.dolphin', RUN_DEADLINE)
        List<String> lines = r.lines
        List<MAVLinkNode> nodes = sitl.comms.nodes()

        then: 'two ArduPlanes told to be QuadPlanes by their EXTENDED_SYS_STATE'
        nodes*.mavLinkId == [31, 32]
        nodes.every { it.family == VehicleFamily.VTOL }

        and:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        resets.values().every { it.accepted() }
        [['Survey Area 1', 'Return to base 1'], ['Survey Area 2', 'Return to base 2']].every { survey, back ->
            int n = vehicleOf(lines, survey)
            int i = after(lines, -1, "mission ${survey} on vehicle ${n}: started")
            i = after(lines, i, "mission ${survey} on vehicle ${n}: cut short: QRTL")
            i = after(lines, i, "mission ${back} on vehicle ${n}: done")
            int landed = after(lines, i, "vehicle { ${n} } landed at *")
            assert parsePosition(lines[landed]).distanceTo(HOME) < 15
            true
        }
        lines.contains('both vehicles back: DONE')

        cleanup:
        watcher?.interrupt()
    }

    def "the VTOL mapping example: a vertical take-off, the survey as a plane, an approach leg added before the vertical landing at home"() {
        given: 'full batteries after the scenario'
        sitl.comms.nodes().each { assert sitl.command(it, MAV_CMD.MAV_CMD_BATTERY_RESET, 1, 100, 0, 0, 0, 0, 0).accepted() }
        String script = 'dsl-examples/vtol-mapping.dolphin'

        when:
        def r = sitl.run(new File(script).text, script, RUN_DEADLINE)
        int n = vehicleOf(r.lines, 'vtol mapping')
        MAVLinkNode node = sitl.comms.node("${n}")

        then:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        inOrder(r.lines, "mission vtol mapping on vehicle ${n}: item 39 added: NAV_WAYPOINT, the approach to the landing after it",
                "mission vtol mapping on vehicle ${n}: item 40 added: NAV_WAYPOINT, the approach to the landing after it",
                "mission vtol mapping on vehicle ${n}: armed", "mission vtol mapping on vehicle ${n}: done", 'mapping: DONE')
        node.home.distanceTo(node.position) < 15
        !node.armed
    }
}
