package dolphin.sim

import com.MAVLink.common.msg_radio_status
import com.MAVLink.enums.MAV_CMD
import dolphin.core.Position
import dolphin.core.SystemClock
import dolphin.mavlink.LinkTimeouts
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.codec.Frame
import dolphin.mission.flight.MissionService
import dolphin.mission.model.MissionItem
import dolphin.mission.transfer.MissionTransferConfig
import dolphin.mission.transfer.TransferPath
import dolphin.testing.MissionLayer
import spock.lang.Specification
import spock.lang.TempDir
import spock.lang.Timeout
import spock.util.concurrent.PollingConditions

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.TimeUnit

/**
 * A simulated copter and our ground station over the SiK radio model (harness/sik_radio.py, the
 * project's venv) at its default profile, in real time: the ground radio's RADIO_STATUS reaches the
 * ground station, a mission goes up over the mission protocol, and a ground station on the ground
 * radio's pseudo-terminal (serial:LINK:57600) hears the vehicle. Needs the venv the build creates;
 * without it the spec fails, it does not skip.
 */
@Timeout(60)
class SikRadioSpec extends Specification {

    static final Path PROJECT = Paths.get('').toAbsolutePath()
    static final Path PYTHON = PROJECT.resolve('.venv/bin/python')
    static final Path SCRIPT = PROJECT.resolve('harness/sik_radio.py')

    @TempDir
    Path tmp

    /** Real time: the radio model runs on the wall clock, and so must the vehicle's streams and timeouts. */
    final SystemClock clock = new SystemClock(1)
    MAVLinkCommunications comms
    SimFleet fleet
    Process radio

    def cleanup() {
        fleet?.close()
        comms?.close()
        if (radio?.alive) {
            radio.destroy()
            if (!radio.waitFor(5, TimeUnit.SECONDS)) {
                radio.destroyForcibly()
            }
        }
    }

    def "over the radio pair, RADIO_STATUS comes from the ground radio (51/68) and a mission goes up"() {
        given:
        comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
        List<Frame> statuses = new CopyOnWriteArrayList<>()
        comms.addObserver { boolean incoming, link, Frame f ->
            if (incoming && f.msgid() == msg_radio_status.MAVLINK_MSG_ID_RADIO_STATUS) {
                statuses << f
            }
        }
        comms.start()
        int vehiclePort = startRadio(['--gcs-port', comms.links()[0].localPort()])
        fleet = new SimFleet(SimFleet.Config.of(1, VehicleKind.COPTER, new InetSocketAddress('127.0.0.1', vehiclePort)), clock)
        fleet.start()

        when: 'the ground station hears the vehicle and its own radio'
        new PollingConditions(timeout: 20, delay: 0.05).eventually {
            assert comms.node('1')?.home != null
            assert !statuses.empty
        }

        then: "the ground radio's report: from system 51 ('3'), component 68 ('D'), its buffer mostly free"
        statuses.every { it.sysid() == 51 && it.compid() == 68 }
        (statuses.last().message() as msg_radio_status).txbuf > 50
        comms.nodes()*.id == ['1']

        when: 'a mission of 12 items goes up item by item'
        MissionService.of(comms).transferConfig = new MissionTransferConfig(LinkTimeouts.DEFAULT, TransferPath.ITEMS)
        def items = mission(comms.node('1').home, 12)
        def up = MissionLayer.uploads(comms.node('1')).upload(items).get(30, TimeUnit.SECONDS)

        then:
        up.success()
        fleet.vehicle(1).mission().size() == items.size()

        and: "the radio's log (written out every second) followed the transfer"
        new PollingConditions(timeout: 5, delay: 0.1).eventually {
            assert Files.readAllLines(tmp.resolve('radio.log')).any { it.contains('pass up MISSION_ITEM_INT seq=11') }
        }
    }

    def "a ground station on the ground radio's pseudo-terminal, as serial:LINK:57600, hears the vehicle"() {
        given:
        Path link = tmp.resolve('radio-tty')
        int vehiclePort = startRadio(['--gcs-pty', link])
        fleet = new SimFleet(SimFleet.Config.of(1, VehicleKind.COPTER, new InetSocketAddress('127.0.0.1', vehiclePort)), clock)
        fleet.start()

        when:
        comms = new MAVLinkCommunications(MAVLinkConfig.of("serial:${link}:57600".toString()), clock)
        comms.start()

        then: "its position, and the vehicle took our telemetry requests through the radios"
        new PollingConditions(timeout: 20, delay: 0.05).eventually {
            assert comms.node('1')?.state()?.position() != null
            assert fleet.vehicle(1).commandsHandled() > 0
        }
    }

    /** Starts the radio model with a free vehicle port and these ground-side options; returns the vehicle port. */
    int startRadio(List<Object> groundSide) {
        assert Files.isExecutable(PYTHON): "needs the project's venv at $PYTHON (bash harness/venv.sh)"
        int vehiclePort = new DatagramSocket(0, InetAddress.getLoopbackAddress()).withCloseable { it.localPort }
        Path out = tmp.resolve('radio.out'), err = tmp.resolve('radio.err')
        radio = new ProcessBuilder(([PYTHON, SCRIPT, '--vehicle-port', vehiclePort, '--seed', 1, '--log', tmp.resolve('radio.log')]
                + groundSide).collect { it.toString() }).directory(PROJECT.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File('/dev/null')))
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start()
        new PollingConditions(timeout: 20, delay: 0.02).eventually {
            assert radio.alive || Files.readString(err).isEmpty(): "sik_radio.py exited: ${Files.readString(err)}"
            assert Files.readString(out).startsWith('ready')
        }
        vehiclePort
    }

    static List<MissionItem> mission(Position home, int count) {
        [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, home, 0, 0, 0, 0),
         MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, home.displace(0, 0, 20), 0, 0, 0, Float.NaN)] +
                (2..<count).collect { i ->
                    MissionItem.at(i, MAV_CMD.MAV_CMD_NAV_WAYPOINT, home.displace(10 * i, 5 * (i % 3), 30 + i), 0, 0, 0, Float.NaN)
                }
    }
}
