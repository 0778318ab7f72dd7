package dolphin.mavlink

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.ardupilotmega.msg_radio
import com.MAVLink.common.msg_radio_status
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import com.MAVLink.standard.msg_global_position_int
import dolphin.core.ManualClock
import dolphin.core.VehicleEvent
import dolphin.mavlink.codec.FrameWriter
import java.time.Duration
import spock.lang.Specification

/**
 * Each link's health: its bytes each way, what it loses, and the telemetry radio's latest report,
 * which makes no vehicle and is no sign of one's life. On a manual clock, with fake links whose bytes
 * are handed to the communications as their reader threads hand them (no socket, no thread).
 */
class LinkHealthSpec extends Specification {

    ManualClock clock = new ManualClock()
    MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
    FakeLink radioLink = new FakeLink('serial:/dev/ttyUSB0:57600', 0)
    FakeLink udpLink = new FakeLink('udpin:0.0.0.0:14559', 1)
    Map<List<Integer>, FrameWriter> writers = [:]
    List<VehicleEvent> events = []

    def setup() {
        comms.attach(radioLink)
        comms.attach(udpLink)
        comms.addVehicleEventListener { events << it }
    }

    /** A message from system {@code sysid} component {@code compid} arrives on {@code link}; its frame's bytes. */
    byte[] hear(FakeLink link, int sysid, int compid, MAVLinkMessage message) {
        byte[] frame = writer(sysid, compid).write(message)
        comms.receive(link.from(frame))
        frame
    }

    FrameWriter writer(int sysid, int compid) {
        writers.computeIfAbsent([sysid, compid]) { new FrameWriter(sysid, compid) }
    }

    static copterHeartbeat() {
        new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA, custom_mode: 3)
    }

    static radioStatus(int rssi, int remrssi, int txbuf) {
        new msg_radio_status(rssi: rssi, remrssi: remrssi, noise: 40, remnoise: 45, rxerrors: 3, fixed: 7, txbuf: txbuf)
    }

    /** Time passes in the communications thread's 250 ms ticks, the contacts checked at each as its timer checks them. */
    void pass(double seconds, Closure each = {}) {
        for (long tick = 1; tick <= Math.round(seconds * 4); tick++) {
            clock.advance(Duration.ofMillis(250))
            each(tick)
            comms.nodes().each { it.contact().check().ifPresent(comms.&publish) }
        }
    }

    def "a SiK radio's RADIO_STATUS from system 51 makes no vehicle, and is its link's latest report"() {
        given:
        clock.advance(Duration.ofSeconds(2))

        when:
        hear(radioLink, 51, 68, radioStatus(170, 160, 97))

        then:
        comms.nodes().isEmpty()
        comms.node('51') == null
        def radio = comms.linkHealth()[0].radio()
        radio == new RadioStatus(170, 160, 40, 45, 3, 7, 97, clock.nanoTime())
        Math.round(radio.rssiDbm()) == -38 && Math.round(radio.remrssiDbm()) == -43
        comms.linkHealth()[0].radioAge() == Duration.ZERO
        comms.linkHealth()[0].radioCurrent()

        and: 'not the other link'
        comms.linkHealth()[1].radio() == null
        !comms.linkHealth()[1].radioCurrent()

        when: 'the vehicle behind the radio sends its heartbeat'
        hear(radioLink, 1, 1, copterHeartbeat())

        then: 'it is discovered, and its link health is its link'
        comms.nodes()*.id == ['1']
        comms.node('1').linkHealth().link() == 'serial:/dev/ttyUSB0:57600'
        comms.node('1').linkHealth().radio() == radio
    }

    def "a radio's report under the vehicle's own system id, from its autopilot or the radio's component, is the link's too, and still makes no vehicle"() {
        when:
        hear(radioLink, 7, compid, radioStatus(120, 110, 50))

        then:
        comms.nodes().isEmpty()
        comms.linkHealth()[0].radio().txbuf() == 50

        when:
        hear(radioLink, 7, 1, copterHeartbeat())
        pass(1)
        hear(radioLink, 7, compid, radioStatus(121, 111, 40))

        then:
        comms.nodes()*.id == ['7']
        comms.node('7').linkHealth().radio() == new RadioStatus(121, 111, 40, 45, 3, 7, 40, clock.nanoTime())

        where:
        compid << [1, 68]
    }

    def "RADIO from older radio firmware is kept as RADIO_STATUS is"() {
        when:
        hear(radioLink, 51, 68, new msg_radio(rssi: 200, remrssi: 190, noise: 30, remnoise: 31, rxerrors: 1, fixed: 2, txbuf: 88))

        then:
        comms.nodes().isEmpty()
        comms.linkHealth()[0].radio() == new RadioStatus(200, 190, 30, 31, 1, 2, 88, clock.nanoTime())
    }

    def "a vehicle heard only through its radio's reports, 51's and under its own ids, goes silent after 3 s and is lost at its timeout"() {
        given:
        hear(radioLink, 1, 1, copterHeartbeat())
        def node = comms.node('1')
        node.connectionTimeout = 10

        when: 'the vehicle stops; the radios go on reporting four times a second'
        pass(12) {
            hear(radioLink, 51, 68, radioStatus(150, 0, 100))
            hear(radioLink, 1, 1, radioStatus(150, 0, 100))
            hear(radioLink, 1, 1, new msg_radio(rssi: 150, txbuf: 100))
        }

        then:
        events*.kind == [VehicleEvent.EventKind.CONTACT_LOST]
        events[0].time() == 3.0d
        node.silence().get() == Duration.ofSeconds(12)
        !node.connected
        node.linkHealth().radioCurrent()
        comms.nodes()*.id == ['1']

        when: 'its heartbeat again'
        hear(radioLink, 1, 1, copterHeartbeat())

        then:
        events*.kind == [VehicleEvent.EventKind.CONTACT_LOST, VehicleEvent.EventKind.CONTACT_AGAIN]
        node.connected
    }

    def "a radio report ages on the clock, and is old news after 5 s"() {
        given:
        hear(radioLink, 51, 68, radioStatus(170, 160, 97))

        when:
        clock.advance(Duration.ofMillis(4900))

        then:
        comms.linkHealth()[0].radioAge() == Duration.ofMillis(4900)
        comms.linkHealth()[0].radioCurrent()

        when:
        clock.advance(Duration.ofMillis(100))

        then:
        comms.linkHealth()[0].radioAge() == Duration.ofSeconds(5)
        !comms.linkHealth()[0].radioCurrent()
        comms.linkHealth()[0].radio().txbuf() == 97
    }

    def "bytes in count everything a link's reader hands over; bytes out every frame written on the link; each per second over the last seconds"() {
        given:
        hear(udpLink, 1, 1, copterHeartbeat())
        def node = comms.node('1')
        long inBefore = comms.linkHealth()[1].bytesIn()

        when: 'ten positions a second come in for 10 s, one of them cut short to garbage; a message a second goes out'
        int positionBytes = 0
        pass(10) { long tick ->
            2.times { positionBytes += hear(udpLink, 1, 1, new msg_global_position_int(lat: 1, lon: 1)).length }
            if (tick % 4 == 0) {
                comms.sendOnCommsThread(node, new msg_heartbeat())
            }
        }
        comms.receive(udpLink.from([0xFD, 9, 0] as byte[]))
        def health = node.linkHealth()

        then:
        health.link() == 'udpin:0.0.0.0:14559'
        health.bytesIn() == inBefore + positionBytes + 3
        health.bytesOut() == udpLink.sent.sum { it.length }
        health.inBytesPerSecond() == positionBytes / 10
        health.outBytesPerSecond() == udpLink.sent.last().length
        health.framesLost() == 0

        and: 'the radio link carried nothing'
        comms.linkHealth()[0].bytesIn() == 0 && comms.linkHealth()[0].inBytesPerSecond() == 0d
    }

    def "a link counts its own bad checksums and the frames lost from its senders' sequence gaps; the communications count all links'"() {
        given:
        hear(radioLink, 1, 1, copterHeartbeat())

        when: 'two frames lost on the air, then one that comes corrupted'
        2.times { writer(1, 1).write(copterHeartbeat()) }
        hear(radioLink, 1, 1, copterHeartbeat())
        byte[] corrupted = writer(1, 1).write(copterHeartbeat())
        corrupted[12] ^= 0x55
        comms.receive(radioLink.from(corrupted))
        hear(radioLink, 1, 1, copterHeartbeat())

        then:
        comms.linkHealth()[0].framesLost() == 3
        comms.linkHealth()[0].badCrcs() == 1
        comms.linkHealth()[0].framesDropped() == 1
        comms.linkHealth()[1].badCrcs() == 0
        comms.drops().frames() == 1
    }

    def "a node on no link of the communications (a spec's) has a health with nothing counted"() {
        given:
        def node = new MAVLinkNode('9', 'UAV', comms, null, null, 9, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)

        expect:
        node.linkHealth() == new LinkHealth('', 0, 0, 0, 0, 0, 0, 0, null, null)
    }
}
