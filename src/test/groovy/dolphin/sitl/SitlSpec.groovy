package dolphin.sitl

import dolphin.testing.MissionLayer
import com.MAVLink.enums.MAV_CMD
import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.CommandResult
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import dolphin.mission.model.Mission
import dolphin.mission.model.MissionType
import dolphin.mission.transfer.MissionVerification
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
 * Dolphin against ArduCopter SITL: two copters on loopback (see README, "Against ArduPilot SITL").
 * Runs only when ARDUPILOT_SITL_BIN names an arducopter binary; otherwise every feature is skipped.
 * The first script starts with the SITL processes, as a user would start it with the vehicles: the
 * missions wait until the vehicles are ready (docs/mavlink.md, "Readiness"). The features build on
 * each other (the vehicles fly one after the other) and follow ArduPilot's own autotest: every wait
 * has a deadline, and every mission is checked by downloading it back.
 */
@Requires({ env.ARDUPILOT_SITL_BIN })
@Stepwise
@Timeout(value = 20, unit = TimeUnit.MINUTES)
class SitlSpec extends Specification {

    /** The home of dsl-examples/two-drones-survey.dolphin and of every-command.dolphin. */
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    /** At SITL's real time, the scenario takes about 7 minutes from boot and the every-command flight about 5. */
    static final Duration RUN_DEADLINE = Duration.ofMinutes(15)
    /** The survey is cut below 70 %: the battery is set just above it once the survey has begun. */
    static final float CUT_BATTERY = 72

    @Shared
    @AutoCleanup
    SitlHarness sitl
    @Shared
    List<MAVLinkNode> nodes
    @Shared
    Map scenario

    def setupSpec() {
        sitl = new SitlHarness()
        // ten metres apart, as the simulated fleet places them; instances 0 and 1: TCP 5760 and 5770 and up
        [1, 2].each { n ->
            sitl.start('ARDUPILOT_SITL_BIN', 'ARDUPILOT_SITL_DEFAULTS', 'copter.parm', 'quad', n, n - 1, HOME.displace(0, 10 * (n - 1), 0))
        }
    }

    def "started with the vehicles, as a user would: the recorded two-vehicle scenario waits for them to be ready, surveys cut below 70 % (battery set to 72 % on the survey), RTL, return missions, landed at home"() {
        given: 'a watcher that sets each battery to 72 % once its vehicle flies the survey (item 2 on, after the take-off)'
        Map<Integer, CommandResult> resets = new ConcurrentHashMap<>()
        Thread watcher = sitl.setBatteriesOnSurvey(resets, 2, CUT_BATTERY)

        when: 'the script starts as soon as the SITL processes do (setupSpec)'
        scenario = sitl.run(new File('dsl-examples/two-drones-survey.dolphin').text, 'dsl-examples/two-drones-survey.dolphin', RUN_DEADLINE)
        List<String> lines = scenario.lines
        nodes = sitl.comms.nodes()

        then: 'two copters, system ids 1 and 2, each waited for until its EKF had a position'
        nodes*.mavLinkId == [1, 2]
        nodes.every { it.family == VehicleFamily.COPTER && it.home.distanceTo(HOME) < 20 }
        [1, 2].every { n -> lines.any { it.startsWith("waiting for vehicle ${n}: ") } }

        and:
        scenario.result.outcome() == ScriptResult.Outcome.COMPLETED
        resets.keySet() == [1, 2] as Set
        resets.values().every { it.accepted() }
        [['Survey Area 1', 'Return to base 1'], ['Survey Area 2', 'Return to base 2']].every { survey, back ->
            int n = vehicleOf(lines, survey)
            int i = after(lines, -1, "mission ${survey} on vehicle ${n}: vehicle ready after *")
            i = after(lines, i, "mission ${survey} on vehicle ${n}: started")
            i = after(lines, i, "mission ${survey} on vehicle ${n}: cut short: RTL")
            int cut = after(lines, i, "vehicle { ${n} } cut short at battery *")
            assert ((lines[cut] =~ /battery (\d+) %/)[0][1] as int) in 50..70
            i = after(lines, cut, "mission ${back} on vehicle ${n}: done")   // landed and disarmed
            int landed = after(lines, i, "vehicle { ${n} } landed at *")
            assert parsePosition(lines[landed]).distanceTo(HOME) < 10
            true
        }
        lines.contains('both vehicles back: DONE')

        cleanup:
        watcher?.interrupt()
    }

    def "each mission of the scenario comes back from its vehicle as built: the return mission left on it, and the survey uploaded again"() {
        expect:
        [['Survey Area 1', 'surveyNorth', 'returnHome'], ['Survey Area 2', 'surveySouth', 'returnHome2']].every { survey, surveyVar, backVar ->
            MAVLinkNode node = sitl.comms.node("${vehicleOf(scenario.lines, survey)}")
            assert roundTripDifference(node, MissionLayer.missionOf(scenario.engine.variable(backVar)), false) == null
            assert roundTripDifference(node, MissionLayer.missionOf(scenario.engine.variable(surveyVar)), true) == null
            true
        }
    }

    def "one copter flies a mission with every family of mission commands to its landing, then unlimited loiters cut short by during"() {
        given: 'full batteries after the scenario'
        nodes.each { assert sitl.command(it, MAV_CMD.MAV_CMD_BATTERY_RESET, 1, 100, 0, 0, 0, 0, 0).accepted() }
        String script = 'src/test/resources/sitl/every-command.dolphin'

        when:
        def r = sitl.run(new File(script).text, script, RUN_DEADLINE)
        List<String> lines = r.lines
        int n = vehicleOf(lines, 'every command')
        MAVLinkNode node = sitl.comms.node("${n}")

        then:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        inOrder(lines, "mission every command on vehicle ${n}: uploading 23 items", "mission every command on vehicle ${n}: armed",
                "mission every command on vehicle ${n}: done", 'every command: DONE',
                "mission holds on vehicle ${n}: started", "mission holds on vehicle ${n}: cut short: RTL", 'holds: DONE')

        when: 'RTL has brought it home'
        SitlHarness.within(300) { assert !node.armed }

        then: 'both missions come back as built: holds as the executor left it, every command uploaded again'
        node.position.distanceTo(HOME) < 15
        roundTripDifference(node, MissionLayer.missionOf(r.engine.variable('holds')), false) == null
        roundTripDifference(node, MissionLayer.missionOf(r.engine.variable('everything')), true) == null
    }

    def "a fenced flight: ArduCopter takes the fence and the rally point (read back equal), and leaving the fence is its breach, RTL and the script's error"() {
        given:
        nodes.each { assert sitl.command(it, MAV_CMD.MAV_CMD_BATTERY_RESET, 1, 100, 0, 0, 0, 0, 0).accepted() }
        SitlHarness.within(300) { assert nodes.every { !it.armed } }
        String script = 'dsl-examples/fence.dolphin'

        when:
        def r = sitl.run(new File(script).text, script, RUN_DEADLINE)
        List<String> lines = r.lines
        int n = vehicleOf(lines, 'fenced flight')
        MAVLinkNode node = sitl.comms.node("${n}")
        Mission m = MissionLayer.missionOf(r.engine.variable('outAndBack'))

        then:
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        // ArduCopter offers MAVLink FTP: each list goes as one file and is read back
        inOrder(lines, "mission fenced flight on vehicle ${n}: fence verified (over FTP)",
                "mission fenced flight on vehicle ${n}: rally points verified (over FTP)",
                "mission fenced flight on vehicle ${n}: upload verified (over FTP)",
                "mission fenced flight on vehicle ${n}: item 2 of 4 reached",
                "the mission stopped: mission fenced flight on vehicle ${n}: vehicle ${n} breached its fence during item 3 of 4 (NAV_WAYPOINT) and left AUTO for RTL (its fence action)*",
                'back home: the fence did its job')

        and: 'what ArduPilot holds is what was sent, as far as it keeps it'
        MissionVerification.firstDifference(MissionType.FENCE, m.fence().items(),
                MissionLayer.downloads(node).download(MissionType.FENCE).get(120, TimeUnit.SECONDS).orThrow()).orElse(null) == null
        MissionVerification.firstDifference(MissionType.RALLY, m.rally().items(),
                MissionLayer.downloads(node).download(MissionType.RALLY).get(120, TimeUnit.SECONDS).orThrow()).orElse(null) == null
    }

    /** Uploads the mission first when asked; then downloads the vehicle's and compares it with the items built for it. */
    String roundTripDifference(MAVLinkNode node, Mission mission, boolean upload) {
        def built = mission.items(node.home)
        if (upload) {
            assert sitl.upload(node, built).success()
        }
        MissionVerification.firstDifference(built, sitl.download(node)).orElse(null)
    }
}
