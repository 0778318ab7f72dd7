package dolphin.sim

import dolphin.core.Position
import java.nio.file.Files
import java.nio.file.Path
import spock.lang.Shared
import spock.lang.Specification

/**
 * The simulated fleet against real ArduPilot: each recording of a SITL session (the project's
 * src/test/resources/sitl-recordings, or -Ddolphin.recordings) is replayed into a simulated vehicle of the
 * same kind, booted when the recorded one was (its heartbeat on the recorded one's phase), with the
 * ground station's frames at the recorded times. What the simulator sends must show the same frames
 * that matter (KeyFrames: modes and arming, MISSION_CURRENT, MISSION_ITEM_REACHED, landed state,
 * ACKs, ground contact, disarm, the plane's RTL, AUTOPILOT_VERSION, every MAVLink FTP reply) in the
 * same order for each kind, and each
 * recording's ending in the order SITL sent it: the copter's first flight started 41 s after boot
 * and after 15 s, both ending in a landing, a disarm and the mission started over; a fence breach
 * ending in RTL, the mission stopped, the copter still descending; a rover's square ending COMPLETE; a
 * plane's circuit ending in its own RTL; a boat's square, driven as the rover drives it; every mission command, then a second mission uploaded over
 * the first, which keeps its current item; a survey with its camera triggers (DO_SET_CAM_TRIGG_DIST between
 * the waypoints, which MISSION_CURRENT never names), ending as the first flight ends; a sub armed before its position estimate, refused AUTO
 * until it had one, then three waypoints at 10 m depth, COMPLETE, and a disarm at depth that resets
 * the mission; dolphin's AMSL items refused by a sub ("Bad alt frame"), on DO_SET_MISSION_CURRENT and
 * again on AUTO, the mission COMPLETE at once; the fence flight and the survey again with their fence,
 * rally points and mission written over MAVLink FTP and read back, the survey's in a burst of five
 * ACKs; a QuadPlane's hop, booted in FLY_BY_WIRE_A (quadplane.parm's mode switch), armed in AUTO:
 * the VTOL take-off reached, the transition's texts, the landing's stages from the airbrake on, the
 * disarm in AUTO at the landing item, then QLOITER, "In landing sequence: mission reset" and the
 * mission NOT_STARTED at 0; a helicopter's first flight: the motor interlock off (DO_AUX_FUNCTION),
 * GUIDED, armed, the interlock on, AUTO refused FAILED ("Mode change to Auto failed: runup not
 * complete") then accepted once the rotor has run up, the copter's flight, landing, disarm and
 * mission started over, and the interlock off again (docs/mavlink.md, "The simulated fleet and real
 * ArduPilot").
 *
 * <p>An FTP reply is compared whole (opcode, the request's, addressee, session, seq, size, offset,
 * burst_complete, its data: the file as the vehicle stores it, or a NAK's error), and so are
 * AUTOPILOT_VERSION's capabilities (FTP, MISSION_INT, COMMAND_INT, fence, rally...) and version. Not
 * compared: when a frame came relative to frames of other kinds (the ground station's frames are
 * replayed at the vehicle's last boot time seen before them, not at the instant they came), and
 * AUTOPILOT_VERSION's git hash and board ids, which name the build, not what it does.
 */
class RecordingConformanceSpec extends Specification {

    static final Path DIRECTORY = Path.of(System.getProperty('dolphin.recordings', 'src/test/resources/sitl-recordings'))
    static final List<String> KINDS = ['HEARTBEAT', 'MISSION_CURRENT', 'MISSION_ITEM_REACHED', 'EXTENDED_SYS_STATE',
                                       'COMMAND_ACK', 'MISSION_ACK', 'STATUSTEXT', 'AUTOPILOT_VERSION', 'FILE_TRANSFER_PROTOCOL']

    /**
     * ArduCopter SITL's EKF uses GPS, so the copter has a position estimate, 41 s after boot (on its
     * own clock, at any speed-up): EKF_STATUS_REPORT's flags in copter-first-flight-at-boot.
     */
    @Shared
    SimOptions sitl = SimOptions.DEFAULT.withWarmup(41)

    /** SITL's --home of the recordings not made at SimDriver.HOME: the subs dived off Comporta, at sea level. */
    static final Map<String, Position> HOMES = ['sub-dive-mission' : Position.fromDegrees(38.43462, -8.86118, 0),
                                                'sub-bad-alt-frame': Position.fromDegrees(38.43462, -8.86118, 0),
                                                'boat-square'      : Position.fromDegrees(38.43462, -8.86118, 0)]

    def setupSpec() {
        assert Files.isDirectory(DIRECTORY): "the SITL recordings are not at ${DIRECTORY.toAbsolutePath().normalize()}" 
    }

    def "#recording: the simulated #kind sends the frames that matter as ArduPilot did"() {
        given:
        def recorded = Recording.read(DIRECTORY.resolve(recording + '.tlog'))
        def real = KeyFrames.of(recorded.vehicle)

        when:
        def simulated = KeyFrames.of(recorded.replay(kind, sitl, HOMES.getOrDefault(recording, SimDriver.HOME)))

        then: 'the recording shows what this spec is about'
        inOrder(real.lines(), ending)

        and: 'the simulator sends the same frames of each kind, in the same order'
        KINDS.each { k -> assert simulated.of(k) == real.of(k) }

        and: 'and ends as SITL did'
        inOrder(simulated.lines(), ending)

        where:
        recording                     | kind               || ending
        'copter-first-flight-at-boot' | VehicleKind.COPTER || ['COMMAND_ACK command=179 result=0', 'COMMAND_ACK command=400 result=0',
                                                               'MISSION_CURRENT seq=4 total=4 state=3', 'EXTENDED_SYS_STATE landed_state=4',
                                                               'STATUSTEXT SIM Hit ground', 'STATUSTEXT Disarming motors',
                                                               'MISSION_CURRENT seq=1 total=4 state=3', 'EXTENDED_SYS_STATE landed_state=1']
        'copter-first-flight'         | VehicleKind.COPTER || ['MISSION_ITEM_REACHED seq=3', 'MISSION_CURRENT seq=4 total=4 state=3',
                                                               'EXTENDED_SYS_STATE landed_state=4', 'STATUSTEXT SIM Hit ground',
                                                               'STATUSTEXT Disarming motors', 'MISSION_CURRENT seq=1 total=4 state=3',
                                                               'HEARTBEAT armed=0 mode=3']
        'copter-fence-breach'         | VehicleKind.COPTER || ['MISSION_CURRENT seq=3 total=4 state=3', 'HEARTBEAT armed=1 mode=6',
                                                               'MISSION_CURRENT seq=3 total=4 state=2', 'EXTENDED_SYS_STATE landed_state=4']
        'rover-square'                | VehicleKind.ROVER  || ['MISSION_ITEM_REACHED seq=3', 'MISSION_CURRENT seq=4 total=4 state=3',
                                                               'MISSION_ITEM_REACHED seq=4', 'MISSION_CURRENT seq=4 total=4 state=5']
        'plane-circuit'               | VehicleKind.PLANE  || ['MISSION_CURRENT seq=5 total=5 state=3', 'HEARTBEAT armed=1 mode=11',
                                                               'MISSION_ITEM_REACHED seq=5', 'STATUSTEXT Mission complete, changing mode to RTL',
                                                               'MISSION_CURRENT seq=5 total=5 state=5']
        'copter-every-command'        | VehicleKind.COPTER || ['MISSION_CURRENT seq=22 total=22 state=3', 'EXTENDED_SYS_STATE landed_state=4',
                                                               'STATUSTEXT SIM Hit ground', 'STATUSTEXT Disarming motors',
                                                               'MISSION_ITEM_REACHED seq=1', 'MISSION_CURRENT seq=2 total=22 state=3',
                                                               'HEARTBEAT armed=0 mode=3', 'MISSION_CURRENT seq=2 total=7 state=3',
                                                               'COMMAND_ACK command=224 result=0', 'MISSION_CURRENT seq=1 total=7 state=3',
                                                               'EXTENDED_SYS_STATE landed_state=3', 'MISSION_CURRENT seq=2 total=7 state=3',
                                                               'HEARTBEAT armed=1 mode=6']
        'boat-square'                 | VehicleKind.BOAT   || ['HEARTBEAT armed=1 mode=10', 'MISSION_ITEM_REACHED seq=3',
                                                               'MISSION_CURRENT seq=4 total=4 state=3', 'MISSION_ITEM_REACHED seq=4',
                                                               'MISSION_CURRENT seq=4 total=4 state=5']
        'copter-survey'               | VehicleKind.COPTER || ['MISSION_CURRENT seq=24 total=24 state=3', 'EXTENDED_SYS_STATE landed_state=4',
                                                               'STATUSTEXT SIM Hit ground', 'STATUSTEXT Disarming motors',
                                                               'MISSION_CURRENT seq=1 total=24 state=3', 'HEARTBEAT armed=0 mode=3']
        'sub-dive-mission'            | VehicleKind.SUB    || ['HEARTBEAT armed=1 mode=19', 'COMMAND_ACK command=176 result=4',
                                                               'STATUSTEXT Mode change failed: Auto requires position',
                                                               'HEARTBEAT armed=1 mode=3', 'MISSION_CURRENT seq=1 total=3 state=3',
                                                               'MISSION_ITEM_REACHED seq=3', 'MISSION_CURRENT seq=3 total=3 state=5',
                                                               'STATUSTEXT Disarming motors', 'MISSION_CURRENT seq=0 total=3 state=5']
        'sub-bad-alt-frame'           | VehicleKind.SUB    || ['MISSION_ACK type=0', 'COMMAND_ACK command=400 result=0',
                                                               'COMMAND_ACK command=224 result=0', 'STATUSTEXT Bad alt frame',
                                                               'COMMAND_ACK command=176 result=0', 'HEARTBEAT armed=1 mode=3']
        'copter-ftp-fence'            | VehicleKind.COPTER || ['AUTOPILOT_VERSION capabilities=64495 flight_sw_version=67633152',
                                                               'FILE_TRANSFER_PROTOCOL NAK req=BurstReadFile to=208/190 session=2 seq=3 size=1 offset=238 burst_complete=1 error=EOF',
                                                               'FILE_TRANSFER_PROTOCOL ACK req=TerminateSession to=208/190 session=5 seq=3 size=0 offset=0 burst_complete=0 data=',
                                                               'FILE_TRANSFER_PROTOCOL NAK req=BurstReadFile to=208/190 session=6 seq=3 size=1 offset=200 burst_complete=1 error=EOF',
                                                               'MISSION_CURRENT seq=3 total=4 state=3', 'HEARTBEAT armed=1 mode=6',
                                                               'MISSION_CURRENT seq=3 total=4 state=2', 'EXTENDED_SYS_STATE landed_state=4']
        'copter-ftp-survey'           | VehicleKind.COPTER || ['AUTOPILOT_VERSION capabilities=64495 flight_sw_version=67633152',
                                                               'FILE_TRANSFER_PROTOCOL ACK req=WriteFile to=208/190 session=1 seq=6 size=0 offset=956 burst_complete=0 data=',
                                                               'FILE_TRANSFER_PROTOCOL ACK req=BurstReadFile to=208/190 session=2 seq=6 size=4 offset=956 burst_complete=1 data=00000100',
                                                               'FILE_TRANSFER_PROTOCOL NAK req=BurstReadFile to=208/190 session=2 seq=7 size=1 offset=960 burst_complete=1 error=EOF',
                                                               'MISSION_CURRENT seq=24 total=24 state=3', 'EXTENDED_SYS_STATE landed_state=4',
                                                               'STATUSTEXT SIM Hit ground', 'STATUSTEXT Disarming motors',
                                                               'MISSION_CURRENT seq=1 total=24 state=3', 'HEARTBEAT armed=0 mode=3']
        'quadplane-hop'               | VehicleKind.QUADPLANE || ['HEARTBEAT armed=1 mode=10', 'MISSION_ITEM_REACHED seq=1',
                                                                  'STATUSTEXT Transition started', 'STATUSTEXT Transition airspeed reached',
                                                                  'STATUSTEXT Transition done', 'MISSION_ITEM_REACHED seq=6',
                                                                  'STATUSTEXT VTOL airbrake', 'MISSION_CURRENT seq=7 total=7 state=3', 'STATUSTEXT VTOL position1',
                                                                  'STATUSTEXT VTOL position2 started', 'STATUSTEXT Land descend started',
                                                                  'EXTENDED_SYS_STATE landed_state=4', 'STATUSTEXT Land final started',
                                                                  'STATUSTEXT Land complete', 'STATUSTEXT Throttle disarmed',
                                                                  'HEARTBEAT armed=0 mode=10', 'COMMAND_ACK command=176 result=0',
                                                                  'HEARTBEAT armed=0 mode=19', 'STATUSTEXT In landing sequence: mission reset',
                                                                  'MISSION_CURRENT seq=0 total=7 state=2']
        'heli-first-flight'           | VehicleKind.HELI      || ['COMMAND_ACK command=218 result=0', 'COMMAND_ACK command=400 result=0',
                                                                  'COMMAND_ACK command=218 result=0', 'COMMAND_ACK command=176 result=4',
                                                                  'STATUSTEXT Mode change to Auto failed: runup not complete',
                                                                  'COMMAND_ACK command=176 result=0', 'HEARTBEAT armed=1 mode=3',
                                                                  'MISSION_CURRENT seq=4 total=4 state=3', 'EXTENDED_SYS_STATE landed_state=4',
                                                                  'STATUSTEXT SIM Hit ground', 'STATUSTEXT Disarming motors',
                                                                  'MISSION_CURRENT seq=1 total=4 state=3', 'HEARTBEAT armed=0 mode=3',
                                                                  'COMMAND_ACK command=218 result=0']
    }

    /** Whether {@code expected} occur in {@code lines} in this order, others between them allowed. */
    static boolean inOrder(List<String> lines, List<String> expected) {
        int at = 0
        for (String e : expected) {
            int i = lines.subList(at, lines.size()).indexOf(e)
            assert i >= 0: "expected '${e}' after the ones before it in:\n${lines.join('\n')}"
            at += i + 1
        }
        true
    }
}
