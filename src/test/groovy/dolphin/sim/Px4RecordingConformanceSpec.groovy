package dolphin.sim

import com.MAVLink.common.msg_home_position
import dolphin.mavlink.Autopilot
import spock.lang.Specification

import static dolphin.sim.RecordingConformanceSpec.DIRECTORY
import static dolphin.sim.RecordingConformanceSpec.inOrder

/**
 * The simulated PX4 copter against real PX4 SITL (SIH quadx; src/test/resources/sitl-recordings/README.md,
 * "PX4"): each px4-copter-* recording is replayed into a simulated PX4 copter as
 * {@link RecordingConformanceSpec} replays ArduPilot's: booted when the recorded one was, at the
 * recording's home (the README's 40.444233, -7.375234, 820, SimDriver.HOME), its position estimate
 * ready when PX4's was (when PX4 set its home: HOME_POSITION's time_usec), the ground station's frames,
 * its heartbeats too (PX4 sends no text before it hears one), at the recorded times. The key frames of
 * each kind ({@link KeyFrames} of a PX4 vehicle: mode by name and arming, MISSION_CURRENT,
 * MISSION_ITEM_REACHED, landed state, COMMAND_ACK, MISSION_ACK, PX4's texts that say what it did,
 * AUTOPILOT_VERSION's capabilities) must be the same, in the same order, and each recording's ending
 * must come in the order SITL sent it: the first flight armed, AUTO.MISSION, MISSION_START, flown
 * item by item, the landing reached as its descent began, "Landing detected"; the fenced hop the same
 * after its fence and rally point, ending in "Mission finished, landed", "Disarmed by landing" and the
 * ground; the refused fence's mission taken, then "Geofence violation for waypoint 3" and NO_MISSION
 * with its 4 items, never armed.
 *
 * <p>Each recording ends when dolphin stopped listening, at the disarm, before PX4 had said all: its
 * texts go out from a queue, after the heartbeat (px4-copter-first-flight's last is "Landing
 * detected", 0.7 s after the disarm), and a MISSION_CURRENT whose seq did not change waits for the next
 * of its 1 Hz ones (px4-copter-fenced-hop's COMPLETE). The simulated frames of a kind past the recorded
 * ones must be those, {@code unsent}.
 *
 * <p>PX4 sends from component 1 only in these recordings (Recording reads every component of system
 * 1). Not compared: the many streams PX4 sends from boot, which the simulator leaves out unless asked
 * for; SET_MESSAGE_INTERVAL's ACKs, as for ArduPilot; when a frame came relative to frames of other
 * kinds, as for ArduPilot: the simulated copter descends at PX4's speeds but climbs and flies at the
 * family's ArduPilot ones, so not in PX4's times (it lands the fenced hop 34 s before SITL's).
 */
class Px4RecordingConformanceSpec extends Specification {

    static final List<String> KINDS = ['HEARTBEAT', 'MISSION_CURRENT', 'MISSION_ITEM_REACHED', 'EXTENDED_SYS_STATE',
                                       'COMMAND_ACK', 'MISSION_ACK', 'STATUSTEXT', 'AUTOPILOT_VERSION']

    def "#recording: the simulated PX4 copter sends the frames that matter as PX4 did"() {
        given:
        def recorded = Recording.read(DIRECTORY.resolve(recording + '.tlog'))
        def real = KeyFrames.of(recorded.vehicle, Autopilot.PX4)
        def px4 = SimOptions.DEFAULT.withAutopilot(Autopilot.PX4).withWarmup(homeSetSeconds(recorded))

        when:
        def simulated = KeyFrames.of(recorded.replay(VehicleKind.COPTER, px4), Autopilot.PX4)

        then: 'the recording shows what this spec is about'
        inOrder(real.lines(), ending)

        and: 'the simulator sends the same frames of each kind, in the same order, and what PX4 had still to say'
        KINDS.each { k -> assert simulated.of(k) == real.of(k) + unsent.findAll { it.startsWith(k + ' ') } }

        and: 'and ends as SITL did'
        inOrder(simulated.lines(), ending)

        where:
        recording                  || ending                                                                     | unsent
        'px4-copter-first-flight'  || ['MISSION_ACK type=0', 'COMMAND_ACK command=400 result=0', 'COMMAND_ACK command=176 result=0',
                                       'COMMAND_ACK command=300 result=0', 'MISSION_CURRENT seq=0 total=4 state=3',
                                       'MISSION_ITEM_REACHED seq=3', 'EXTENDED_SYS_STATE landed_state=4',
                                       'STATUSTEXT Landing detected']                                            | ['STATUSTEXT Mission finished, landed',
                                                                                                                    'STATUSTEXT Disarmed by landing']
        'px4-copter-fenced-hop'    || ['MISSION_CURRENT seq=0 total=4 state=2', 'COMMAND_ACK command=400 result=0',
                                       'COMMAND_ACK command=300 result=0', 'MISSION_ITEM_REACHED seq=3',
                                       'EXTENDED_SYS_STATE landed_state=4', 'STATUSTEXT Landing detected',
                                       'STATUSTEXT Mission finished, landed', 'STATUSTEXT Disarmed by landing',
                                       'EXTENDED_SYS_STATE landed_state=1']                                      | ['MISSION_CURRENT seq=3 total=4 state=5']
        'px4-copter-fence-refused' || ['COMMAND_ACK command=179 result=0', 'MISSION_ACK type=0',
                                       'STATUSTEXT Geofence violation for waypoint 3',
                                       'MISSION_CURRENT seq=0 total=4 state=1']                                  | []
    }

    /** When PX4 set its home, its position estimate ready: seconds after boot. */
    static double homeSetSeconds(Recording recorded) {
        recorded.vehicle.find { it instanceof msg_home_position }.time_usec / 1e6
    }
}
