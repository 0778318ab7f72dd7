package dolphin.mavlink

import com.MAVLink.ardupilotmega.msg_radio
import com.MAVLink.common.msg_radio_status
import com.MAVLink.minimal.msg_heartbeat
import com.MAVLink.standard.msg_global_position_int
import dolphin.core.ManualClock
import dolphin.core.VehicleEvent
import java.time.Duration
import spock.lang.Specification

import static dolphin.core.VehicleEvent.EventKind.CONTACT_AGAIN
import static dolphin.core.VehicleEvent.EventKind.CONTACT_LOST

/**
 * When a vehicle is silent and when it is heard again (docs/decisions.md, "Contact"), on a manual
 * clock with the vehicle's messages and the 250 ms check handed to its contact as the communications
 * thread hands them (no socket, no real time); and how the communications hand the events on.
 */
class ContactSpec extends Specification {

    static final int HEARTBEAT = msg_heartbeat.MAVLINK_MSG_ID_HEARTBEAT
    static final int POSITION = msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT
    static final int RADIO_STATUS = msg_radio_status.MAVLINK_MSG_ID_RADIO_STATUS
    static final int RADIO = msg_radio.MAVLINK_MSG_ID_RADIO

    ManualClock clock = new ManualClock()
    MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', comms, null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)
    List<VehicleEvent> events = []

    /** A message from the vehicle's autopilot, now. */
    void hear(int msgid) {
        node.contact().heard(msgid).ifPresent(events.&add)
    }

    /** Time passes in the communications thread's 250 ms ticks; {@code each} runs at each tick (its number from 1) before the check. */
    void pass(double seconds, Closure each = {}) {
        long ticks = Math.round(seconds * 4)
        for (long tick = 1; tick <= ticks; tick++) {
            clock.advance(Duration.ofMillis(250))
            each(tick)
            node.contact().check().ifPresent(events.&add)
        }
    }

    def "a vehicle silent for 3 s raises one CONTACT_LOST, however long the silence lasts"() {
        given:
        hear(HEARTBEAT)

        when:
        pass(2.75)

        then: 'not yet'
        events.isEmpty()
        !node.silence().present

        when:
        pass(0.25)
        pass(15)

        then:
        events == [new VehicleEvent('1', CONTACT_LOST, 'no contact for 3 s', 3.0d)]
        events[0].line() == 'vehicle 1: no contact for 3 s'
        node.silence().get() == Duration.ofSeconds(18)
    }

    def "RADIO_STATUS and RADIO, even under the vehicle's own ids as a router relays them, neither keep it heard nor end its silence"() {
        given:
        hear(HEARTBEAT)

        when: 'only the telemetry radio speaks, every quarter second'
        pass(20) {
            hear(RADIO_STATUS)
            hear(RADIO)
        }

        then:
        events*.kind == [CONTACT_LOST]
        events[0].time() == 3.0d
        node.silence().get() == Duration.ofSeconds(20)
        !Contact.isSignOfLife(RADIO_STATUS) && !Contact.isSignOfLife(RADIO)
        Contact.isSignOfLife(HEARTBEAT) && Contact.isSignOfLife(POSITION)
    }

    def "a message after #silent s of silence raises one CONTACT_AGAIN of #said s, rounded down as the table counts; a later silence is a new one"() {
        given:
        hear(HEARTBEAT)
        pass(silent)

        when:
        hear(POSITION)
        pass(2) { hear(POSITION) }

        then:
        events*.kind == [CONTACT_LOST, CONTACT_AGAIN]
        events[1] == new VehicleEvent('1', CONTACT_AGAIN, "contact again after ${said} s", silent)
        !node.silence().present

        when:
        pass(3)

        then:
        events*.kind == [CONTACT_LOST, CONTACT_AGAIN, CONTACT_LOST]

        where:
        silent | said
        31d    | 31
        31.75d | 31
        3d     | 3
    }

    def "silences of #gap s raise nothing"() {
        given:
        hear(HEARTBEAT)

        when:
        10.times {
            pass(gap)
            hear(HEARTBEAT)
        }

        then:
        events.isEmpty()
        !node.silence().present
        clock.seconds() == 10 * gap

        where:
        gap << [2d, 2.75d]
    }

    def "a vehicle heard steadily, heartbeats at 1 Hz and positions at 4 Hz, raises nothing in ten minutes"() {
        when:
        pass(600) { long tick ->
            hear(POSITION)
            if (tick % 4 == 0) {
                hear(HEARTBEAT)
            }
        }

        then:
        events.isEmpty()
        !node.silence().present
    }

    def "the communications hand an event to every listener on the publishing thread; one that throws stops none of the others"() {
        given:
        def heard = []
        comms.addVehicleEventListener { throw new IllegalStateException('listener bug') }
        comms.addVehicleEventListener { heard << [it, Thread.currentThread().name] }
        def lost = new VehicleEvent('1', CONTACT_LOST, 'no contact for 3 s', 3)

        when:
        Thread.start('publisher') { comms.publish(lost) }.join()

        then:
        heard == [[lost, 'publisher']]
    }
}
