package dolphin.platform

import com.MAVLink.common.msg_radio_status
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.ManualClock
import dolphin.docs.LinkHealthExample
import dolphin.mavlink.FakeLink
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.codec.FrameWriter
import java.time.Duration
import spock.lang.Specification

/** What a program embedding the engine reads of a vehicle's link through the platform (docs/embedding.md, "Link health"). */
class PlatformLinkHealthSpec extends Specification {

    ManualClock clock = new ManualClock()
    MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
    MAVLinkPlatform platform = new MAVLinkPlatform(comms)
    FakeLink udp = new FakeLink('udpin:0.0.0.0:14559', 0)
    FakeLink radio = new FakeLink('serial:/dev/ttyUSB0:57600', 1)

    def setup() {
        comms.attach(udp)
        comms.attach(radio)
    }

    void hear(FakeLink link, int sysid, int compid, def message) {
        comms.receive(link.from(new FrameWriter(sysid, compid).write(message)))
    }

    def "each vehicle's link health by its id: the radio on its own link only; nothing for an unknown id"() {
        given:
        def hb = new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA)
        hear(udp, 1, 1, hb)
        hear(radio, 2, 1, hb)
        hear(radio, 51, 68, new msg_radio_status(rssi: 124, remrssi: 118, txbuf: 41))

        expect:
        comms.nodes()*.id == ['1', '2']
        platform.linkHealth('1').get().link() == 'udpin:0.0.0.0:14559'
        platform.linkHealth('1').get().radio() == null
        platform.linkHealth('2').get().link() == 'serial:/dev/ttyUSB0:57600'
        platform.linkHealth('2').get().radio().txbuf() == 41
        platform.linkHealth('2').get().bytesIn() > 0
        platform.linkHealth('51').empty
        comms.linkHealth()*.link() == ['udpin:0.0.0.0:14559', 'serial:/dev/ttyUSB0:57600']
    }

    def "the status bar of docs/embedding.md's example: the rates, and the radio while its report is current"() {
        given:
        def hb = new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA)
        hear(radio, 1, 1, hb)
        hear(radio, 51, 68, new msg_radio_status(rssi: 124, remrssi: 118, txbuf: 97))

        when:
        clock.advance(Duration.ofSeconds(1))

        then:
        LinkHealthExample.statusBar(platform, '1') ==~ /serial:\/dev\/ttyUSB0:57600: \d+\.\d\/\d+\.\d kB\/s radio -62\/-65 dBm txbuf 97%/
        LinkHealthExample.statusBar(platform, '2') == ''

        when:
        clock.advance(Duration.ofSeconds(5))

        then:
        LinkHealthExample.statusBar(platform, '1') == 'serial:/dev/ttyUSB0:57600: 0.0/0.0 kB/s'
    }
}
