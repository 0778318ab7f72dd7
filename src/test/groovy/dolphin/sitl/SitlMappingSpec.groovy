package dolphin.sitl

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.ardupilotmega.msg_camera_feedback
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkNode
import dolphin.mission.file.PlanFile
import dolphin.mission.model.Mission
import dolphin.mission.model.MissionItem
import dolphin.mission.survey.MappingItem
import dolphin.mission.transfer.MissionVerification
import dolphin.mission.transfer.TransferResult
import dolphin.testing.MissionLayer
import java.nio.file.Files
import java.nio.file.Path
import java.time.Duration
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import spock.lang.AutoCleanup
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Timeout

import static dolphin.testing.ScriptLines.inOrder

/**
 * QGroundControl's complex items (docs/qgc-surveys.md) on ArduCopter SITL, one copter with a servo
 * camera (CAM1_TYPE 1 from a parameter file): a survey and a corridor scan flown to the landing,
 * every camera trigger item run and every photo reported in CAMERA_FEEDBACK; and the corpus'
 * structure scan, whose plan stores no items, rebuilt by the plan reader and uploaded: ArduCopter
 * refuses the plan's SET_CAMERA_MODE and QGroundControl's DO_SET_ROI_WPNEXT_OFFSET, and stores the
 * scan as Dolphin builds it (docs/decisions.md, "Camera triggers on ArduPilot"). Runs only when
 * ARDUPILOT_SITL_BIN names an arducopter binary; the structure scan also needs the corpus beside
 * the repository (-Ddolphin.missionFiles).
 */
@Requires({ env.ARDUPILOT_SITL_BIN })
@Timeout(value = 20, unit = TimeUnit.MINUTES)
class SitlMappingSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final int SYSID = 41
    /** The mapping flight (2 km of survey and corridor) ends about 90 s after boot at --speedup 5: some 8 minutes at real time. */
    static final Duration RUN_DEADLINE = Duration.ofMinutes(15)
    static final String STRUCTURE_SCAN = 'surveys/ZilantRobotics+innopolis_vtol_dynamics/tests/inspection/technopark_structure_scan.plan'
    /** AP_Mission::start_command announces each item it starts, "Mission: 5 SetCamTrigDst". */
    static final String TRIGGER_STARTED = /^Mission: (\d+) SetCamTrigDst$/

    @Shared
    @AutoCleanup
    SitlHarness sitl
    @Shared
    CameraReports reports

    def setupSpec() {
        sitl = new SitlHarness()
        reports = CameraReports.listeningTo(sitl.comms, SYSID)
        sitl.start('ARDUPILOT_SITL_BIN', 'ARDUPILOT_SITL_DEFAULTS', 'copter.parm', 'quad', SYSID, 40, HOME, ['CAM1_TYPE 1'])
    }

    def "a survey and a corridor scan flown to the landing: every trigger item run, as many photos reported as QGroundControl counts, within one per trigger item and 5 %"() {
        given:
        String script = 'src/test/resources/sitl/mapping.dolphin'

        when:
        def r = sitl.run(new File(script).text, script, RUN_DEADLINE)
        List<String> lines = r.lines
        MAVLinkNode node = sitl.comms.node("${SYSID}")
        Mission mission = MissionLayer.missionOf(r.engine.variable('mapping'))
        List<MappingItem> mapping = mission.commandList.findAll { it instanceof MappingItem } as List<MappingItem>
        List<MissionItem> built = mission.items(node.home)
        Set<Integer> triggers = built.findAll { it.command() == MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST }*.seq() as Set
        int expected = mapping.sum { it.coverage().photos() } as int

        then: 'the executor flew it to its end, and the copter landed at home'
        r.result.outcome() == ScriptResult.Outcome.COMPLETED
        mapping*.qgcType() == ['survey', 'CorridorScan']
        inOrder(lines, "mission mapping on vehicle ${SYSID}: armed", "mission mapping on vehicle ${SYSID}: done")
        lines.contains('mapping: DONE')
        SitlHarness.within(60) { assert !node.armed }
        node.position.distanceTo(HOME) < 10

        and: 'ArduCopter started every DO_SET_CAM_TRIGG_DIST (MISSION_CURRENT names only waypoints) and warned of none'
        triggers.size() >= 4
        reports.triggersStarted == triggers
        reports.warnings.isEmpty()

        and: 'one CAMERA_FEEDBACK a photo: as many as QGroundControl counts, give or take one per trigger item (each takes one at once) and 5 % (ArduPilot measures straight from the last photo, across the turns)'
        expected > 0
        Math.abs(reports.feedback.get() - expected) <= triggers.size() + expected / 20
        reports.lastImageIndex.get() == reports.feedback.get()

        cleanup:
        println "mapping: ${reports.feedback.get()} CAMERA_FEEDBACK, ${expected} photos counted (${mapping.collect { it.coverage() }}), ${triggers.size()} trigger items"
    }

    @Requires({ System.getProperty('dolphin.missionFiles') })
    def "the corpus' structure scan, rebuilt from its plan: stored as built once its SET_CAMERA_MODE is left out; QGroundControl's DO_SET_ROI_WPNEXT_OFFSET would be refused"() {
        given:
        Path plan = Path.of(System.getProperty('dolphin.missionFiles')).resolve(STRUCTURE_SCAN)
        assert Files.isRegularFile(plan): "the corpus has no ${STRUCTURE_SCAN}"
        List<MissionItem> items = PlanFile.read(plan)
        SitlHarness.within(300) { assert sitl.comms.nodes().any { it.mavLinkId == SYSID && it.home != null } }
        MAVLinkNode node = sitl.comms.node("${SYSID}")
        int cameraMode = items.findIndexOf { it.command() == MAV_CMD.MAV_CMD_SET_CAMERA_MODE }
        List<MissionItem> forArduCopter = renumbered(items.findAll { it.command() != MAV_CMD.MAV_CMD_SET_CAMERA_MODE })
        int roi = forArduCopter.findIndexOf { it.command() == MAV_CMD.MAV_CMD_DO_SET_ROI_LOCATION }
        // QGroundControl's item where Dolphin puts the region of interest: params 5-7 pitch 0, roll 0, yaw 90
        List<MissionItem> asQgc = forArduCopter.collect {
            it.seq() == roi ? new MissionItem(roi, MAV_CMD.MAV_CMD_DO_SET_ROI_WPNEXT_OFFSET, MissionItem.MISSION, 0, 0, 0, 0, 0, 0, 90, true) : it
        }

        expect: 'the plan rebuilt: 6 simple items, then the scan of 10 layers round 4 vertices ((4 + 3) x 10 + 4 items), then the landing'
        items.size() == 1 + 6 + 74 + 1
        items.count { it.command() == MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST } == 20
        cameraMode == 1
        roi > 0

        when: 'as read: SET_CAMERA_MODE (a PX4 plan\'s), with its reserved params NaN, is refused by AP_Mission::sanity_check_params'
        TransferResult asRead = sitl.upload(node, items)

        then:
        !asRead.success()
        asRead.error().contains("item 1 (")
        asRead.error().contains('MAV_MISSION_INVALID_PARAM3')

        when: 'with QGroundControl\'s DO_SET_ROI_WPNEXT_OFFSET, which is not a mission command on ArduPilot'
        TransferResult qgc = sitl.upload(node, asQgc)
        List<MissionItem> kept = sitl.download(node)

        then: 'refused there: the vehicle holds the items before it, then what is left of its last mission (AP_Mission::truncate only shortens)'
        !qgc.success()
        qgc.error().contains("item ${roi} (")
        qgc.error().contains('MAV_MISSION_UNSUPPORTED')
        kept.size() >= roi
        MissionVerification.firstDifference(forArduCopter.take(roi), kept.take(roi)).orElse(null) == null

        when: 'as Dolphin builds it, without the SET_CAMERA_MODE'
        TransferResult stored = sitl.upload(node, forArduCopter)

        then: 'ArduCopter takes it and gives it back as built: the region of interest, the layers, the 20 trigger items, DO_SET_ROI_NONE, the landing'
        stored.success()
        MissionVerification.firstDifference(forArduCopter, sitl.download(node)).orElse(null) == null
        forArduCopter.size() == items.size() - 1
    }

    static List<MissionItem> renumbered(List<MissionItem> items) {
        items.withIndex().collect { MissionItem item, int i -> item.withSeq(i) }
    }

    /**
     * What the copter says of its camera, from its autopilot's messages: each CAMERA_FEEDBACK (one a
     * photo without a feedback pin), the trigger items AP_Mission announced starting, and every
     * STATUSTEXT of severity warning or worse once the mission has started (before, the pre-arm
     * checks complain until the EKF has a position).
     */
    static class CameraReports implements MAVLinkCommunications.ComponentListener {
        final int sysid
        final AtomicInteger feedback = new AtomicInteger()
        final AtomicInteger lastImageIndex = new AtomicInteger()
        final Set<Integer> triggersStarted = ConcurrentHashMap.newKeySet()
        final List<String> warnings = Collections.synchronizedList([])
        private volatile boolean started

        CameraReports(int sysid) {
            this.sysid = sysid
        }

        static CameraReports listeningTo(MAVLinkCommunications comms, int sysid) {
            def reports = new CameraReports(sysid)
            comms.addComponentListener(reports)
            reports
        }

        @Override
        void message(MAVLinkNode node, int component, MAVLinkMessage message) {
            if (node.mavLinkId != sysid || component != 1) {
                return
            }
            if (message instanceof msg_camera_feedback) {
                feedback.incrementAndGet()
                lastImageIndex.accumulateAndGet(message.img_idx, Math::max)
            } else if (message instanceof msg_statustext) {
                String text = message.text
                started |= text.startsWith('Mission: ')
                def trigger = text =~ TRIGGER_STARTED
                if (trigger.matches()) {
                    triggersStarted << (trigger.group(1) as int)
                } else if (started && message.severity <= 4) {   // MAV_SEVERITY_WARNING and worse
                    warnings << text
                }
            }
        }
    }
}
