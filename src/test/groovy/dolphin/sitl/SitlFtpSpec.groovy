package dolphin.sitl

import com.MAVLink.common.msg_file_transfer_protocol
import com.MAVLink.enums.MAV_CMD
import dolphin.core.Position
import dolphin.mavlink.LinkTimeouts
import dolphin.mavlink.MAVLinkNode
import dolphin.mission.model.Fence
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import dolphin.mission.model.RallyPoints
import dolphin.mission.transfer.MissionTransferConfig
import dolphin.mission.transfer.MissionTransfers
import dolphin.mission.transfer.SimMissionTransferSpec
import dolphin.mission.transfer.MissionVerification
import dolphin.mission.transfer.TransferPath
import dolphin.mission.transfer.TransferResult
import dolphin.mission.transfer.TransferStatus
import dolphin.mission.flight.MissionService
import java.util.concurrent.TimeUnit
import spock.lang.AutoCleanup
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification
import spock.lang.Stepwise
import spock.lang.Timeout

/**
 * Mission transfers over MAVLink FTP with a real ArduCopter SITL (ARDUPILOT_SITL_BIN): the list
 * written as @MISSION/mission.dat, read back equal, downloaded the same over FTP and item by item; a
 * list ArduPilot cannot convert refused when the file is closed.
 */
@Requires({ env.ARDUPILOT_SITL_BIN })
@Stepwise
@Timeout(value = 5, unit = TimeUnit.MINUTES)
class SitlFtpSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    @Shared
    @AutoCleanup
    SitlHarness sitl
    @Shared
    MAVLinkNode node

    def setupSpec() {
        sitl = new SitlHarness()
        sitl.start('ARDUPILOT_SITL_BIN', 'ARDUPILOT_SITL_DEFAULTS', 'copter.parm', 'quad', 7, 0, HOME)
        // a vehicle that has just booted answers MAV_MISSION_NO_SPACE and refuses files: wait for its home
        SitlHarness.within(120) { assert sitl.comms.node('7')?.home != null }
        node = sitl.comms.node('7')
    }

    static List<MissionItem> mission(int waypoints) {
        [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
         MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, HOME.displace(0, 0, 20), 0, 0, 0, Float.NaN)] +
                (0..<waypoints).collect { i ->
                    MissionItem.at(2 + i, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME.displace(10 * i, 5 * (i % 3), 30 + i), 0, 0, 0, Float.NaN)
                }
    }

    MissionTransfers transfers() {
        MissionService.of(sitl.comms).vehicle(node).transfers()
    }

    static MissionTransferConfig on(TransferPath path) {
        new MissionTransferConfig(LinkTimeouts.DEFAULT, path)
    }

    def "a mission of 60 waypoints uploaded over FTP is read back equal, and downloads the same over FTP and item by item"() {
        given:
        List<MissionItem> items = mission(60)
        List<TransferStatus> statuses = Collections.synchronizedList([])

        when:
        TransferResult up = transfers().upload().upload(MissionType.MISSION, items, on(TransferPath.FTP), { statuses << it })
                .get(60, TimeUnit.SECONDS)
        TransferResult overFtp = transfers().download().download(MissionType.MISSION, on(TransferPath.FTP), null).get(60, TimeUnit.SECONDS)
        TransferResult byItems = transfers().download().download(MissionType.MISSION, on(TransferPath.ITEMS), null).get(60, TimeUnit.SECONDS)

        then:
        up.success()
        up.verified()
        up.note() == 'over FTP'
        statuses.last().text() == "uploading over FTP: ${String.format('%,d', 2 * (10 + 62 * 38))} of ${String.format('%,d', 2 * (10 + 62 * 38))} bytes".toString()
        overFtp.note() == 'over FTP'
        MissionVerification.firstDifference(items, overFtp.orThrow()).isEmpty()
        MissionVerification.firstDifference(items, byItems.orThrow()).isEmpty()
        node.roundTrip().samples() > 0
    }

    def "the mission, a fence and rally points uploaded over FTP are verified by ArduPilot's CRC of its copy: nothing is read back"() {
        given:
        Position home = node.home
        List<Integer> opcodes = Collections.synchronizedList([])
        sitl.comms.addObserver { boolean incoming, link, frame ->
            if (!incoming && frame.message() instanceof msg_file_transfer_protocol) {
                opcodes << (frame.message().payload[3] & 0xff)
            }
        }
        Fence fence = SimMissionTransferSpec.fenceAround(home)
        RallyPoints rally = SimMissionTransferSpec.rallyAround(home)
        List<MissionItem> survey = mission(40) + [MissionItem.command(42, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 1, 7.5f, -1, 0),
                                                  MissionItem.command(43, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, 12.5f, 0, 1, 0)]

        when:
        List<TransferResult> up = [transfers().upload().upload(MissionType.MISSION, survey, on(TransferPath.FTP), null),
                                   transfers().upload().upload(MissionType.FENCE, fence.items(), on(TransferPath.FTP), null),
                                   transfers().upload().upload(MissionType.RALLY, rally.items(), on(TransferPath.FTP), null)]
                *.get(60, TimeUnit.SECONDS)

        then:
        up.every { it.success() && it.verified() }
        opcodes.count { it == 14 } == 3   // CalcFileCRC32
        opcodes.count { it == 4 } == 0    // OpenFileRO
    }

    def "a DO_JUMP to item 0 is refused when the file is closed"() {
        given:
        List<MissionItem> items = mission(2) + [MissionItem.command(4, MAV_CMD.MAV_CMD_DO_JUMP, 0, 1, 0, 0)]

        when:
        TransferResult r = transfers().upload().upload(MissionType.MISSION, items, on(TransferPath.FTP), null).get(60, TimeUnit.SECONDS)

        then:
        !r.success()
        r.error() == 'upload to vehicle 7 failed: over FTP: the vehicle refused @MISSION/mission.dat when closing it:' +
                ' FailErrno, errno 22 (EINVAL): ArduPilot could not read a complete list from it'
    }
}
