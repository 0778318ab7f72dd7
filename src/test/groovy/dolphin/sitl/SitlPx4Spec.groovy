package dolphin.sitl

import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.Autopilot
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import java.time.Duration
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
 * Dolphin against two PX4 quadcopters: PX4 SITL with its built-in simulator (SIH, model quadx),
 * instances 0 and 1 (system ids 1 and 2), at the examples' home, the first script started 10 s after
 * they are heard ({@link SitlHarness#settle}; docs/px4.md). Their simulated batteries drain over SIM_BAT_DRAIN = 500 s of flight, so that the
 * scenario's 70 % cut comes during the survey. Runs only when PX4_SITL_BIN names the px4 binary.
 */
@Requires({ env.PX4_SITL_BIN })
@Stepwise
@Timeout(value = 20, unit = TimeUnit.MINUTES)
class SitlPx4Spec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final Duration RUN_DEADLINE = Duration.ofMinutes(12)

    @Shared
    @AutoCleanup
    SitlHarness sitl

    def setupSpec() {
        sitl = new SitlHarness(SitlHarness.px4Links(2))
        (0..1).each { sitl.startPx4('quadx', it, HOME, [SIM_BAT_DRAIN: 500]) }
        sitl.settle(2, 10)
    }

    def "the report's two-vehicle scenario on two PX4 quadcopters: surveys cut below 70 % by AUTO.RTL, return missions, landed and disarmed at home"() {
        when:
        def r = sitl.run(new File('dsl-examples/two-drones-survey.dolphin').text, 'dsl-examples/two-drones-survey.dolphin', RUN_DEADLINE)
        List<String> lines = r.lines
        List<MAVLinkNode> nodes = sitl.comms.nodes()

        then:
        nodes*.mavLinkId.sort() == [1, 2]
        nodes.every { it.state().autopilot() == Autopilot.PX4 && it.family == VehicleFamily.COPTER }
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        [['Survey Area 1', 'Return to base 1'], ['Survey Area 2', 'Return to base 2']].every { survey, back ->
            int n = vehicleOf(lines, survey)
            int i = after(lines, -1, "mission ${survey} on vehicle ${n}: upload verified*")
            i = after(lines, i, "mission ${survey} on vehicle ${n}: started")
            i = after(lines, i, "mission ${survey} on vehicle ${n}: item *")
            i = after(lines, i, "mission ${survey} on vehicle ${n}: cut short: AUTO.RTL")
            i = after(lines, i, "mission ${back} on vehicle ${n}: done")
            int landed = after(lines, i, "vehicle { ${n} } landed at *")
            assert parsePosition(lines[landed]).distanceTo(HOME) < 15
            true
        }
        lines.contains('both vehicles back: DONE')
        nodes.every { !it.armed }
    }

    def "a fenced flight: the fence, its return point and a rally point read back equal, the flight inside it to its landing"() {
        given:
        String script = 'src/test/resources/sitl/px4-fence.dolphin'

        when:
        def r = sitl.run(new File(script).text, script, RUN_DEADLINE)
        int n = vehicleOf(r.lines, 'fenced hop')
        MAVLinkNode node = sitl.comms.node("${n}")

        then:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        inOrder(r.lines, "mission fenced hop on vehicle ${n}: fence verified*", "mission fenced hop on vehicle ${n}: rally points verified*",
                "mission fenced hop on vehicle ${n}: upload verified*", "mission fenced hop on vehicle ${n}: started",
                "mission fenced hop on vehicle ${n}: done", 'fenced hop: DONE, fence breached: false')
        node.position.distanceTo(HOME) < 15
        !node.armed
    }

    def "the fence example: PX4 refuses before the flight a mission that leaves its fence, and says why"() {
        given:
        String script = 'dsl-examples/fence.dolphin'

        when:
        def r = sitl.run(new File(script).text, script, RUN_DEADLINE)
        // the mission never starts: its vehicle is the task's
        int n = (r.lines.find { it ==~ /task fenced flight started on vehicle \d+/ } =~ /(\d+)$/)[0][1] as int

        then:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        r.lines.any { it == "the mission stopped: mission fenced flight on vehicle ${n}: vehicle ${n} found the mission infeasible: 'Geofence violation for waypoint 3'" }
        !sitl.comms.node("${n}").armed
    }
}
