package dolphin.mavlink

import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.SystemClock
import dolphin.mavlink.codec.FrameReader
import dolphin.mavlink.codec.FrameWriter
import dolphin.mavlink.link.LinkUrl
import dolphin.sim.FaultModel
import dolphin.sim.SimOptions
import dolphin.sim.VehicleKind
import spock.lang.Specification
import spock.lang.Timeout
import spock.util.concurrent.PollingConditions
import java.util.concurrent.TimeUnit

import static dolphin.core.VehicleEvent.EventKind.LINK_CHANGED

@Timeout(60)
class LinkSpec extends Specification {

    def "connection strings parse, and bad ones say what was expected"() {
        expect:
        LinkUrl.parse('udpin:0.0.0.0:14559').kind() == LinkUrl.Transport.UDPIN
        LinkUrl.parse('udpout:127.0.0.1:14550').port() == 14550
        LinkUrl.parse('tcp:localhost:5760').host() == 'localhost'
        with(LinkUrl.parse('serial:/dev/ttyUSB0:57600')) { device() == '/dev/ttyUSB0' && baud() == 57600 && bytesPerSecond().asDouble == 5760 }
        with(LinkUrl.parse('udpin:0.0.0.0:14550?bps=115200')) { port() == 14550 && bps() == 115200 && bytesPerSecond().asDouble == 11520 }
        with(LinkUrl.parse('serial:/dev/ttyUSB0:115200?bps=57600')) { baud() == 115200 && bytesPerSecond().asDouble == 5760 }
        LinkUrl.parse('udpin:0.0.0.0:14559').bytesPerSecond().empty

        when:
        LinkUrl.parse(text)

        then:
        def e = thrown(IllegalArgumentException)
        e.message.contains(fragment)

        where:
        text                 | fragment
        'udpin'              | 'expected KIND:ADDRESS'
        'ftp:host:21'        | "unknown link kind 'ftp'"
        'tcp:host'           | 'expected HOST:PORT'
        'tcp:host:0'         | 'between 1 and 65535'
        'udpout:host:x'      | "the port must be a number, got 'x'"
        'udpin:h:1?baud=9'   | "unknown option 'baud=9': the only one is ?bps="
        'udpin:h:1?bps=0'    | 'the bits per second must be positive'
        'serial:/dev/ttyS0'  | 'expected DEVICE:BAUD'
        'serial:/dev/ttyS0:0'| 'the baud rate must be positive'
    }

    def "a TCP link connects to a vehicle's server, discovers it and sends our heartbeat on the stream"() {
        given: 'a TCP "vehicle" like SITL SERIAL0: it sends heartbeats split across writes'
        def server = new ServerSocket(0, 1, InetAddress.loopbackAddress)
        def heard = new java.util.concurrent.CopyOnWriteArrayList()
        def vehicle = Thread.start {
          try {
            server.accept().withCloseable { s ->
                s.soTimeout = 100
                def w = new FrameWriter(5, 1)
                def r = new FrameReader()
                byte[] buf = new byte[1024]
                long end = System.nanoTime() + 20_000_000_000L
                while (System.nanoTime() < end && !Thread.currentThread().interrupted) {
                    byte[] f = w.write(new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA, custom_mode: 4))
                    s.outputStream.write(f, 0, 5)
                    s.outputStream.flush()
                    s.outputStream.write(f, 5, f.length - 5)
                    try {
                        int n = s.inputStream.read(buf)
                        if (n > 0) {
                            r.feed(buf, 0, n, { heard << it })
                        }
                    } catch (SocketTimeoutException ignored) {
                    }
                }
            }
          } catch (IOException closedAtCleanup) {
          }
        }
        def comms = new MAVLinkCommunications(MAVLinkConfig.of("tcp:127.0.0.1:${server.localPort}"), new SystemClock(1))

        when:
        comms.start()

        then:
        new PollingConditions(timeout: 10).eventually {
            assert comms.node('5')?.modeName == 'GUIDED'
            assert heard.any { it.msgid == 0 && it.sysid == 208 && it.compid == 190 }
        }

        cleanup:
        comms?.close()
        vehicle?.interrupt()
        server?.close()
    }

    def "a TCP link to nowhere fails to open with the link's name"() {
        given:
        int port = new ServerSocket(0).withCloseable { it.localPort }

        when:
        new MAVLinkCommunications(MAVLinkConfig.of("tcp:127.0.0.1:${port}"), new SystemClock(1)).start()

        then:
        def e = thrown(IOException)
        e.message.contains("cannot connect to tcp:127.0.0.1:${port}")
    }

    def "a udpin port already in use fails to open with the link's name"() {
        given:
        def taken = new DatagramSocket(0, InetAddress.loopbackAddress)

        when:
        new MAVLinkCommunications(MAVLinkConfig.of("udpin:127.0.0.1:${taken.localPort}"), new SystemClock(1)).start()

        then:
        def e = thrown(IOException)
        e.message.contains("cannot listen on udpin:127.0.0.1:${taken.localPort}")

        cleanup:
        taken?.close()
    }

    def "two links at once: vehicles on each are discovered, and the same system id on both is two vehicles"() {
        given:
        def h = new FleetHarness(MAVLinkConfig.of('udpin:127.0.0.1:0', 'udpin:127.0.0.1:0'))
        def second = new InetSocketAddress('127.0.0.1', h.comms.links()[1].localPort())
        h.fleet(1)
        // the id a vehicle gets depends on which is heard first: the first link's, then the second's
        h.eventually { assert h.comms.nodes()*.id == ['1'] }
        def other = new dolphin.sim.SimFleet(dolphin.sim.SimFleet.Config.of(1, VehicleKind.PLANE, second), h.clock)
        other.start()

        expect:
        h.eventually {
            assert h.comms.nodes()*.id == ['1', '1@2']
        }
        h.comms.nodes()*.family == [VehicleFamily.COPTER, VehicleFamily.PLANE]

        cleanup:
        other?.close()
        h?.close()
    }

    def "streams are established through duplicated, delayed and reordered datagrams"() {
        given:
        def h = new FleetHarness()
        h.fleet(1, VehicleKind.COPTER, 1, SimOptions.DEFAULT, new FaultModel(0.1, 0.3, 0.05, 0.2, 99))

        expect:
        h.eventually(20) {
            def s = h.node('1')?.state()
            assert s?.position() != null && s.systemStatus() != null && s.home() != null
        }

        cleanup:
        h?.close()
    }

    def "one simulated vehicle relayed to two udpin links is one vehicle, commanded through the first link, then through the second when the first is cut"() {
        given: 'a copter whose datagrams a relay copies to both links; in real time, so a busy machine cannot stretch a copy past the 2 s and 4 s of telling the links apart'
        def h = new FleetHarness(MAVLinkConfig.of('udpin:127.0.0.1:0', 'udpin:127.0.0.1:0'), 1)
        def events = new java.util.concurrent.CopyOnWriteArrayList<dolphin.core.VehicleEvent>()
        h.comms.addVehicleEventListener { events << it }
        def relay = new DatagramRelay(h.comms.links().collect { new InetSocketAddress('127.0.0.1', it.localPort()) })
        def fleet = h.fleet(dolphin.sim.SimFleet.Config.of(1, VehicleKind.COPTER, relay.address()))

        expect: 'one vehicle on both links, with its telemetry'
        h.eventually {
            assert h.comms.nodes()*.id == ['1']
            assert h.node('1').getLinks().toSet() == h.comms.links().toSet()
            assert h.node('1').state().position() != null
        }
        // which link's reader thread queues a datagram first varies: either may discover the vehicle
        def (first, second) = h.node('1').getLinks()
        h.node('1').getLink() == first
        h.comms.command(h.node('1'), MAV_CMD.MAV_CMD_DO_SET_MODE, 1f, 4f).get(10, TimeUnit.SECONDS).accepted()
        h.eventually { assert h.node('1').duplicatesOn(first) + h.node('1').duplicatesOn(second) > 20 }

        when: 'the first path is cut'
        relay.cut << first.index()

        then: 'the vehicle goes on through the second, without a silence'
        h.eventually { assert h.node('1').getLink() == second }
        events*.kind == [LINK_CHANGED, LINK_CHANGED]
        h.comms.command(h.node('1'), MAV_CMD.MAV_CMD_DO_SET_MODE, 1f, 0f).get(10, TimeUnit.SECONDS).accepted()
        h.eventually { assert fleet.vehicle(1).modeName() == 'STABILIZE' }

        cleanup:
        h?.close()
        relay?.close()
    }
}
