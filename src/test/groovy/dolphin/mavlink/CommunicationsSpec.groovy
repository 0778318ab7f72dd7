package dolphin.mavlink

import dolphin.platform.MAVLinkPlatform
import com.MAVLink.common.msg_command_long
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SYS_STATUS_SENSOR
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.core.VehicleEvent
import dolphin.mavlink.codec.DropCounters
import dolphin.mavlink.codec.FrameWriter
import dolphin.mavlink.codec.SigningKey
import dolphin.sim.FaultModel
import dolphin.sim.SimOptions
import dolphin.sim.VehicleKind
import spock.lang.AutoCleanup
import spock.lang.Specification

/** The ground station against simulated vehicles over real UDP on loopback. */
class CommunicationsSpec extends Specification {

    @AutoCleanup
    FleetHarness h = new FleetHarness()

    def "vehicles with distinct system ids on one port are discovered with their type and family"() {
        when:
        h.fleet(2, VehicleKind.COPTER, 1)
        h.fleet(1, VehicleKind.PLANE, 3)

        then:
        h.eventually {
            assert h.comms.nodes()*.id == ['1', '2', '3']
        }
        h.comms.nodes()*.type == ['UAV', 'UAV', 'UAV']
        h.comms.nodes()*.family == [VehicleFamily.COPTER, VehicleFamily.COPTER, VehicleFamily.PLANE]
        h.eventually {
            assert h.comms.nodes()*.modeName == ['STABILIZE', 'STABILIZE', 'MANUAL']
        }
    }

    def "a camera component's heartbeat neither creates a vehicle nor overwrites the autopilot's mode"() {
        given:
        h.fleet(1)
        h.eventually { assert h.node('1')?.modeName == 'STABILIZE' }
        def camera = new FrameWriter(1, 100)
        def other = new FrameWriter(7, 100)
        def socket = new DatagramSocket()
        def hb = new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_CAMERA, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_INVALID, custom_mode: 6)

        when: 'a camera of system 1, and a lone camera with system id 7, send heartbeats'
        10.times {
            [camera, other].each { w ->
                byte[] f = w.write(hb)
                socket.send(new DatagramPacket(f, f.length, new InetSocketAddress('127.0.0.1', h.port())))
            }
        }

        then:
        h.eventually { assert h.comms.framesIn() > 25 }
        h.node('1').modeName == 'STABILIZE'
        h.node('1').autopilotCompid == 1
        h.comms.nodes()*.id == ['1']

        cleanup:
        socket?.close()
    }

    def "telemetry is requested on discovery, so position, home and battery arrive from a copter that streams nothing by default"() {
        given:
        def fleet = h.fleet(1)
        def sim = fleet.vehicle(1)

        expect: 'the copter streams nothing until asked'
        sim.streams().isEmpty() || h.node('1') != null

        when:
        h.eventually {
            def s = h.node('1')?.state()
            assert s?.position() != null && s.systemStatus() != null && s.home() != null
        }
        def node = h.node('1')

        then:
        sim.streams().keySet().containsAll([1, 33, 42, 147, 242, 245])
        node.position.distanceTo(sim.position()) < 0.05
        node.home.distanceTo(sim.home()) < 0.05
        node.batteryRemaining() == 1.0d
    }

    def "a vehicle that refuses SET_MESSAGE_INTERVAL gets REQUEST_DATA_STREAM instead"() {
        given:
        def fleet = h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT.withoutMessageInterval())

        expect:
        h.eventually {
            def s = h.node('1')?.state()
            assert s?.position() != null && s.systemStatus() != null
        }
        fleet.vehicle(1).streams().keySet().containsAll([1, 33])
    }

    def "streams that fall silent are asked for again"() {
        given:
        def fleet = h.fleet(1)
        h.eventually { assert h.node('1')?.state()?.position() != null }
        def node = h.node('1')

        when: 'the vehicle forgets the requested rates, as after a reboot'
        fleet.vehicle(1).resetStreams()
        long before = node.state().positionNanos()

        then:
        h.eventually(15) {
            assert h.comms.telemetryRerequests('1') > 0
            assert node.state().positionNanos() > before
        }
        fleet.vehicle(1).streams().containsKey(33)
    }

    def "streams are established over a link that loses a third of the datagrams both ways"() {
        given:
        h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT, new FaultModel(0.33, 0, 0, 0, 42))

        expect:
        h.eventually(20) {
            def s = h.node('1')?.state()
            assert s?.position() != null && s.systemStatus() != null && s.home() != null
        }
    }

    def "battery follows the vehicle, and MAV_CMD_BATTERY_RESET sets it"() {
        given:
        def fleet = h.fleet(1)
        h.eventually { assert h.node('1')?.state()?.systemStatus() != null }

        when:
        def result = h.comms.command(h.node('1'), MAV_CMD.MAV_CMD_BATTERY_RESET, 255, 42).get()

        then:
        result.accepted()
        fleet.vehicle(1).battery() == 42d
        h.eventually { assert h.node('1').batteryRemaining() == 0.42d }

        when: 'a mask without battery instance 0, the only one the vehicle has'
        def other = h.comms.command(h.node('1'), MAV_CMD.MAV_CMD_BATTERY_RESET, 2, 90).get()

        then:
        other.result() == MAV_RESULT.MAV_RESULT_FAILED
        fleet.vehicle(1).battery() == 42d
    }

    def "a vehicle that stops is lost after its connection timeout, and found again when it comes back"() {
        given:
        def fleet = h.fleet(2)
        h.eventually { assert h.comms.nodes().size() == 2 }
        h.node('1').connectionTimeout = 5

        when:
        fleet.vehicle(1).silent = true
        double silentAt = h.clock.seconds()

        then: 'lost no earlier than 5 s of clock time after its last heartbeat'
        h.eventually { assert !h.node('1').connected }
        h.clock.seconds() - silentAt >= 4
        h.node('2').connected
        new MAVLinkPlatform(h.comms).connectedNodes.ids() == ['2']

        when:
        fleet.vehicle(1).silent = false

        then:
        h.eventually { assert h.node('1').connected }
    }

    def "a vehicle that stops sending raises contact lost after 3 s and contact again when it sends, long before its timeout"() {
        given:
        def fleet = h.fleet(1)
        h.eventually { assert h.node('1')?.state()?.position() != null }
        List<VehicleEvent> events = new java.util.concurrent.CopyOnWriteArrayList<>()
        h.comms.addVehicleEventListener { events << it }

        when:
        fleet.vehicle(1).silent = true
        double silentAt = h.clock.seconds()

        then:
        h.eventually { assert events*.kind == [VehicleEvent.EventKind.CONTACT_LOST] }
        events[0].text() == 'no contact for 3 s'
        events[0].time() - silentAt >= 2.5
        h.eventually { assert h.node('1').silence().get().toSeconds() >= 5 }
        h.node('1').connected

        when:
        fleet.vehicle(1).silent = false

        then:
        h.eventually { assert events*.kind == [VehicleEvent.EventKind.CONTACT_LOST, VehicleEvent.EventKind.CONTACT_AGAIN] }
        (events[1].text() =~ /contact again after (\d+) s/)[0][1] as int >= 5
        !h.node('1').silence().present
    }

    def "arming is refused with the vehicle's PreArm text during its warm-up, then accepted; SYS_STATUS shows the pre-arm checks"() {
        given:
        long prearm = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK
        h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT.withWarmup(30))
        h.eventually { assert h.node('1')?.state()?.systemStatus() != null }
        def node = h.node('1')

        when:
        def early = h.comms.command(node, MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, 1).get()

        then:
        early.result() == MAV_RESULT.MAV_RESULT_FAILED
        h.eventually { assert node.state().statusTexts().contains('PreArm: Need Position Estimate') }
        !node.armed
        with(node.state().systemStatus()) {
            (onboard_control_sensors_present & prearm) != 0
            (onboard_control_sensors_enabled & prearm) != 0
            (onboard_control_sensors_health & prearm) == 0
        }

        when: 'after the warm-up (30 s of clock time)'
        h.eventually(10) { assert h.clock.seconds() > 31 }
        h.eventually { assert (node.state().systemStatus().onboard_control_sensors_health & prearm) != 0 }
        def late = h.comms.command(node, MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, 1).get()

        then:
        late.accepted()
        h.eventually { assert node.armed }
    }

    def "a copter refuses to arm in AUTO; a mode change is acknowledged and shows in the heartbeat"() {
        given:
        h.fleet(1)
        h.eventually { assert h.node('1') != null }
        def node = h.node('1')

        when:
        def auto = h.comms.command(node, MAV_CMD.MAV_CMD_DO_SET_MODE, 1, 3).get()
        def arm = h.comms.command(node, MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, 1).get()

        then:
        auto.accepted()
        arm.result() == MAV_RESULT.MAV_RESULT_FAILED
        h.eventually { assert node.modeName == 'AUTO' && node.state().statusTexts().contains('Arm: AUTO mode not armable') }

        when:
        def guided = h.comms.command(node, MAV_CMD.MAV_CMD_DO_SET_MODE, 1, 4).get()
        def bogus = h.comms.command(node, MAV_CMD.MAV_CMD_DO_SET_MODE, 1, 77).get()

        then:
        guided.accepted()
        bogus.result() == MAV_RESULT.MAV_RESULT_FAILED
        h.eventually { assert node.modeName == 'GUIDED' }
    }

    def "command acknowledgements are addressed to the ground station that sent the command"() {
        given:
        h.fleet(1)
        h.eventually { assert h.node('1') != null }
        def acks = new java.util.concurrent.CopyOnWriteArrayList()
        h.comms.addObserver { incoming, link, frame -> if (incoming && frame.msgid() == 77) acks << frame.message() }

        when:
        h.comms.command(h.node('1'), MAV_CMD.MAV_CMD_BATTERY_RESET, 255, 50).get()

        then:
        h.eventually { assert !acks.isEmpty() }
        acks[0].target_system == 208
        acks[0].target_component == 190
    }

    def "DO_SET_HOME moves the vehicle's home, which comes back in HOME_POSITION"() {
        given:
        h.fleet(1)
        h.eventually { assert h.node('1')?.home != null }

        when:
        def r = h.comms.command(h.node('1'), MAV_CMD.MAV_CMD_DO_SET_HOME, 0, 0, 0, 0, 40.5f, -7.5f, 900).get()

        then:
        r.accepted()
        h.eventually { assert h.node('1').home.distanceTo(Position.fromDegrees(40.5, -7.5, 900)) < 1 }
    }

    def "a command nobody answers ends with no COMMAND_ACK after its #attempts attempts"() {
        given: 'a vehicle that goes silent right after discovery'
        h.close()
        h = new FleetHarness(MAVLinkConfig.of('udpin:127.0.0.1:0').withCommandAttempts(attempts))
        def fleet = h.fleet(1)
        h.eventually { assert h.node('1') != null }
        fleet.vehicle(1).silent = true
        int before = fleet.vehicle(1).commandsHandled()

        when:
        def r = h.comms.command(h.node('1'), MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, 1).get()

        then:
        r.result() == CommandResult.NO_ACK
        r.attempts() == attempts
        fleet.vehicle(1).commandsHandled() == before

        where:
        attempts << [MAVLinkConfig.of('udpin:127.0.0.1:0').commandAttempts(), 2]
    }

    def "a command needs at least one attempt"() {
        when:
        MAVLinkConfig.of('udpin:127.0.0.1:0').withCommandAttempts(0)

        then:
        def e = thrown(IllegalArgumentException)
        e.message == 'a command needs at least one attempt, got 0'
    }

    def "with a signing key, signed frames pass and unsigned or wrongly signed ones are dropped and counted"() {
        given:
        def key = SigningKey.fromPassphrase('dolphin fleet')
        h.close()
        h = new FleetHarness(MAVLinkConfig.of('udpin:127.0.0.1:0').withSigningKey(key))

        when:
        h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT, FaultModel.NONE, key)
        h.fleet(1, VehicleKind.COPTER, 2, SimOptions.DEFAULT, FaultModel.NONE, null)
        h.fleet(1, VehicleKind.COPTER, 3, SimOptions.DEFAULT, FaultModel.NONE, SigningKey.fromPassphrase('intruder'))

        then: 'the signed vehicle is discovered and answers our signed requests'
        h.eventually {
            assert h.node('1')?.state()?.position() != null
            assert h.comms.drops().get(DropCounters.Reason.UNSIGNED) > 0
            assert h.comms.drops().get(DropCounters.Reason.BAD_SIGNATURE) > 0
        }
        h.comms.nodes()*.id == ['1']
    }

    def "frames from systems outside the allow-list are ignored"() {
        given:
        h.close()
        h = new FleetHarness(MAVLinkConfig.of('udpin:127.0.0.1:0').withAllowedSysids([2] as Set))

        when:
        h.fleet(2)

        then:
        h.eventually { assert h.comms.filtered() > 0 && h.node('2') != null }
        h.comms.nodes()*.id == ['2']
    }

    def "closing releases the port and stops the thread"() {
        given:
        int port = h.port()

        when:
        h.close()
        def again = new DatagramSocket(new InetSocketAddress('127.0.0.1', port))

        then:
        again.localPort == port
        !Thread.allStackTraces.keySet()*.name.contains('MAVLink communications')

        cleanup:
        again?.close()
    }

    def "garbage and unknown messages on the port do not stop the communications"() {
        given:
        h.fleet(1)
        def socket = new DatagramSocket()
        def rnd = new Random(7)

        when:
        200.times {
            byte[] junk = new byte[rnd.nextInt(300) + 1]
            rnd.nextBytes(junk)
            socket.send(new DatagramPacket(junk, junk.length, new InetSocketAddress('127.0.0.1', h.port())))
        }
        def cmd = new msg_command_long(command: 9999, target_system: 1)
        byte[] f = new FrameWriter(9, 1).write(cmd)
        socket.send(new DatagramPacket(f, f.length, new InetSocketAddress('127.0.0.1', h.port())))

        then:
        h.eventually { assert h.node('1')?.state()?.position() != null }
        h.comms.drops().get(DropCounters.Reason.GARBAGE_BYTES) > 0

        cleanup:
        socket?.close()
    }
}
