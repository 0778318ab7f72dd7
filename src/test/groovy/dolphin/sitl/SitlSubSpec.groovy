package dolphin.sitl

import com.MAVLink.enums.MAV_TYPE
import dolphin.core.Position
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import dolphin.sensor.FleetFile
import dolphin.sensor.SensorService
import java.nio.file.Path
import java.time.Duration
import java.util.concurrent.TimeUnit
import spock.lang.AutoCleanup
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.testing.ScriptLines.parsePosition

/**
 * Dolphin against three ArduSub SITL (`--model vectored`, sub.parm) off Comporta, home at sea level
 * as ArduSub needs it (docs/decisions.md, "ArduSub behaviour"), 10 m apart: one per vehicle of
 * dsl-examples/uuv-fleet.json, with the fleet file's system ids (instances 20 and up, so their ports
 * never clash with the other specs' vehicles), the fleet file given to the ground station as
 * `dolphin run --fleet` gives it. Runs only when ARDUPILOT_SITL_SUB_BIN names an ardusub binary;
 * otherwise every feature is skipped.
 */
@Requires({ env.ARDUPILOT_SITL_SUB_BIN })
@Timeout(value = 30, unit = TimeUnit.MINUTES)
class SitlSubSpec extends Specification {

    static final Position HOME = Position.fromDegrees(38.43462, -8.86118, 0)
    static final Path FLEET = Path.of('dsl-examples/uuv-fleet.json')
    static final String SURVEYS = 'dsl-examples/listing1-uuv-surveys.dolphin'
    /** Deeper than this (metres below home) is under water, not bobbing at the surface. */
    static final double AT_DEPTH = -1
    /** Within this of home's height (metres) is at the surface. */
    static final double AT_SURFACE = 1

    @Shared
    @AutoCleanup
    SitlHarness sitl
    @Shared
    SitlReports reports
    @Shared
    List<Integer> sysids

    def setupSpec() {
        FleetFile fleet = FleetFile.read(FLEET)
        sysids = fleet.vehicles().keySet().sort()
        assert sysids.size() == 3: "${FLEET} should name three subs, names ${sysids}"
        sitl = new SitlHarness()
        SensorService.of(sitl.comms).useFleet(fleet)
        reports = SitlReports.listeningTo(sitl.comms)
        sysids.eachWithIndex { int sysid, int i ->
            sitl.start('ARDUPILOT_SITL_SUB_BIN', 'ARDUPILOT_SITL_SUB_DEFAULTS', 'sub.parm', 'vectored', sysid, 20 + i, HOME.displace(0, 10 * i, 0))
        }
    }

    def "the three subs are picked as UUVs at the surface near their homes once they know where they are"() {
        given: 'a position from each (ArduSub sends latitude and longitude 0 until its EKF has an origin, about 20 s after boot)'
        String script = 'src/test/resources/sitl/subs-at-surface.dolphin'
        SitlHarness.within(180) {
            assert sitl.comms.nodes().size() == 3 && sitl.comms.nodes().every { it.state().position() != null }
        }

        when:
        def r = sitl.run(new File(script).text, script, Duration.ofMinutes(3))

        then: 'three ArduSubs with the fleet file\'s system ids, announcing themselves as submarines'
        r.result.exitCode() == 0
        sitl.comms.nodes()*.mavLinkId.sort() == sysids
        sitl.comms.nodes().every { it.family == VehicleFamily.SUB && it.type == 'UUV' }
        sysids.every { reports.heartbeatTypes[it] == [MAV_TYPE.MAV_TYPE_SUBMARINE] as Set }

        and: 'each where SITL put it, 10 m apart, at the surface'
        sysids.eachWithIndex { int sysid, int i ->
            String line = r.lines.find { it.startsWith("vehicle { ${sysid} }: a UUV at ") }
            assert line: "no position of vehicle ${sysid}:\n${r.lines.join('\n')}"
            Position at = parsePosition(line)
            assert Position.fromDegrees(at.latitudeDegrees(), at.longitudeDegrees(), 0).distanceTo(HOME.displace(0, 10 * i, 0)) < 5
            assert Math.abs(at.hae()) < AT_SURFACE
        }
    }

    def "listing 1: each sub surveys at depth from the uploaded, verified mission, every item reached, and is back at the surface at the end"() {
        when:
        def r = sitl.run(new File(SURVEYS).text, SURVEYS, Duration.ofMinutes(25))
        List<String> lines = r.lines

        then:
        r.result.exitCode() == 0
        sysids.every { int sysid ->
            assert verifiedMissions(lines, sysid): "no verified upload on vehicle ${sysid}:\n${lines.join('\n')}"
            true
        }

        and: 'each went under water (the lowest relative_alt it reported) and reached the last item of each mission it flew'
        sysids.every { int sysid ->
            assert reports.lowestRelativeAlt[sysid] < AT_DEPTH
            verifiedMissions(lines, sysid).each { String mission ->
                int last = lastItem(lines, mission, sysid)
                assert lines.contains("mission ${mission} on vehicle ${sysid}: item ${last} of ${last} reached".toString())
                assert reports.itemsReached[sysid]?.contains(last)
            }
            true
        }

        and: 'each is back at the surface (its last GLOBAL_POSITION_INT may be a moment behind the script\'s end)'
        SitlHarness.within(10) {
            sysids.each { int sysid ->
                MAVLinkNode node = sitl.comms.node("${sysid}")
                assert Math.abs(node.state().relativeAlt()) < AT_SURFACE
            }
        }
    }

    /** The missions uploaded to this vehicle and verified, from the executor's "upload verified" lines. */
    static List<String> verifiedMissions(List<String> lines, int sysid) {
        lines.findResults { (it =~ /^mission (.+) on vehicle ${sysid}: upload verified( \(.+\))?$/).with { m -> m.matches() ? m.group(1) : null } }.unique()
    }

    /** The number of items of a mission (home not counted), from the executor's "item k of K reached" lines. */
    static int lastItem(List<String> lines, String mission, int sysid) {
        String prefix = "mission ${mission} on vehicle ${sysid}: item "
        String line = lines.find { it.startsWith(prefix) && it.endsWith(' reached') }
        assert line: "no item of ${mission} reached on vehicle ${sysid}:\n${lines.join('\n')}"
        (line =~ / of (\d+) reached$/)[0][1] as int
    }
}
