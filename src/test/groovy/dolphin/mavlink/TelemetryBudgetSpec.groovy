package dolphin.mavlink

import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_command_long
import com.MAVLink.common.msg_home_position
import com.MAVLink.common.msg_radio_status
import com.MAVLink.common.msg_sys_status
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import com.MAVLink.standard.msg_global_position_int
import dolphin.core.ManualClock
import dolphin.mavlink.codec.FrameReader
import dolphin.mavlink.codec.FrameWriter
import java.time.Duration
import spock.lang.Specification
import spock.lang.Unroll

/** The telemetry asked of the vehicles on one link, fitted to its bandwidth; on a manual clock with fake links. */
class TelemetryBudgetSpec extends Specification {

    static final int POSITION = msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT
    static final int SYS_STATUS = msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS
    static final int HOME = msg_home_position.MAVLINK_MSG_ID_HOME_POSITION

    @Unroll
    def "#vehicles vehicles on a link of #bytes bytes/s: every stream at its wanted rate"() {
        when:
        TelemetryBudget.StreamRates plan = TelemetryBudget.plan(4, vehicles, bytes)

        then:
        !plan.slowed()
        plan.fits()
        plan.hz()[POSITION] == 4d
        plan.hz()[SYS_STATUS] == 4d
        plan.hz()[HOME] == 1d

        where:
        vehicles | bytes
        1        | Double.NaN
        1000     | Double.NaN
        1        | 5760
        4        | 5760      // a SiK radio pair per vehicle, or four on one: about 660 bytes/s each, under half of 5760
    }

    def "a full link slows the streams in their documented order, position and battery last, never below their slowest"() {
        given:
        List<String> order = TelemetryBudget.STREAMS*.name()

        expect: 'as vehicles are added to a 57600-baud link, the first stream slowed is the first in the order'
        (5..40).each { n ->
            TelemetryBudget.StreamRates plan = TelemetryBudget.plan(4, n, 5760)
            def slowed = TelemetryBudget.STREAMS.findAll { s -> plan.hz()[s.msgid()] < (s.fast() ? 4d : 1d) }*.name()
            assert slowed == order.take(slowed.size())
            assert TelemetryBudget.STREAMS.every { s -> plan.hz()[s.msgid()] >= s.slowestHz() }
            assert !plan.fits() || plan.bytesPerSecond() <= 0.5 * 5760
        }

        and: 'five vehicles slow the home position and the EKF report to their slowest, then the extended state and the battery'
        TelemetryBudget.plan(4, 5, 5760).slowedText(4) == 'HOME_POSITION 0.1 Hz, EKF_STATUS_REPORT 0.2 Hz, EXTENDED_SYS_STATE 0.5 Hz, BATTERY_STATUS 0.5 Hz'

        and: 'forty cannot fit even at the slowest rates: position at 1 Hz, SYS_STATUS at 0.5 Hz, and it says so'
        with(TelemetryBudget.plan(4, 40, 5760)) {
            !fits()
            hz()[POSITION] == 1d
            hz()[SYS_STATUS] == 0.5d
        }
    }

    def "a link whose stated bandwidth is unlimited never slows, however many vehicles"() {
        expect:
        !TelemetryBudget.plan(4, 1000, Double.NaN).slowed()
    }

    ManualClock clock = new ManualClock()
    MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)

    /** The SET_MESSAGE_INTERVAL asked of system {@code sysid} for {@code msgid}, in Hz, latest first. */
    static List<Double> asked(FakeLink link, int sysid, int msgid) {
        List<Double> hz = []
        link.sent.each { byte[] bytes ->
            new FrameReader().feed(bytes, 0, bytes.length) { f ->
                def m = f.message()
                if (m instanceof msg_command_long && m.command == MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL
                        && m.target_system == sysid && m.param1 == msgid) {
                    hz.add(0, 1e6d / m.param2)
                }
            }
        }
        hz
    }

    /** A copter's heartbeat; then every command sent to it is acknowledged, as a vehicle does, one after the other. */
    void heartbeat(FakeLink link, int sysid) {
        def hb = new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA)
        comms.receive(link.from(new FrameWriter(sysid, 1).write(hb)))
        acknowledge(link)
    }

    int acknowledged

    void acknowledge(FakeLink link) {
        while (acknowledged < link.sent.size()) {
            byte[] bytes = link.sent[acknowledged++]
            new FrameReader().feed(bytes, 0, bytes.length) { f ->
                def m = f.message()
                if (m instanceof msg_command_long) {
                    def ack = new msg_command_ack(command: m.command, result: (short) MAV_RESULT.MAV_RESULT_ACCEPTED)
                    comms.receive(link.from(new FrameWriter(m.target_system, 1).write(ack)))
                }
            }
        }
    }

    def "the fifth copter on one 57600-baud radio slows the home position of all five; a UDP link next to it is left alone"() {
        given:
        FakeLink radio = new FakeLink('serial:/dev/ttyUSB0:57600', 0)
        FakeLink udp = new FakeLink('udpin:0.0.0.0:14559', 1)
        comms.attach(radio)
        comms.attach(udp)

        when:
        (1..4).each { heartbeat(radio, it) }
        acknowledged = 0
        (11..20).each { heartbeat(udp, it) }

        then:
        (1..4).every { asked(radio, it, HOME) == [1d] && asked(radio, it, POSITION) == [4d] }

        when:
        acknowledged = 0
        heartbeat(radio, 5)

        then: 'the first four asked again, the fifth asked once, at the slower rate'
        (1..4).every { asked(radio, it, HOME) == [0.1d, 1d] && asked(radio, it, POSITION) == [4d] }
        asked(radio, 5, HOME) == [0.1d]
        (11..20).every { asked(udp, it, HOME) == [1d] }
    }

    def "a SiK radio heard on a UDP link whose rate was not stated: the five copters on it are slowed to fit 57600 baud; a link without one is left alone"() {
        given: 'the communications thread run by hand, on the manual clock'
        MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
        FakeLink relay = new FakeLink('udpin:0.0.0.0:14550', 0)
        FakeLink lte = new FakeLink('udpin:0.0.0.0:14560', 1)
        comms.attachForSpecs([relay, lte])
        Closure run = { Duration d ->
            for (long t = 0; t < d.toMillis(); t += 10) {
                clock.advance(Duration.ofMillis(10))
                comms.runDue()
                [relay, lte].each { link -> acknowledgeQueued(comms, link) }
            }
        }
        def hb = new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA)

        when: 'five copters on the relay and five on LTE, heard for 2 s'
        (1..5).each { comms.received(relay.from(new FrameWriter(it, 1).write(hb))) }
        (11..15).each { comms.received(lte.from(new FrameWriter(it, 1).write(hb))) }
        run(Duration.ofSeconds(2))

        then: 'nothing known of either link: every stream at its wanted rate'
        (1..5).collect { asked(relay, it, HOME) } == [[1d]] * 5
        (11..15).collect { asked(lte, it, HOME) } == [[1d]] * 5

        when: 'the ground radio on the relay reports (SiK: system 51, component 68)'
        def report = new msg_radio_status(rssi: 180, remrssi: 170, txbuf: 95, noise: 40, remnoise: 38)
        comms.received(relay.from(new FrameWriter(51, 68).write(report)))
        run(Duration.ofSeconds(2))

        then: 'the five on the relay share 5760 bytes/s: their home position slowed to 0.1 Hz, position kept'
        (1..5).collect { asked(relay, it, HOME) } == [[0.1d, 1d]] * 5
        (1..5).every { asked(relay, it, POSITION).every { it == 4d } }   // asked again only as silent (no fake sends it)
        (11..15).collect { asked(lte, it, HOME) } == [[1d]] * 5
    }

    /** Acknowledges the commands sent on {@code link} since the last call, through the communications' queue. */
    private final Map<FakeLink, Integer> queuedAcks = [:].withDefault { 0 }

    void acknowledgeQueued(MAVLinkCommunications comms, FakeLink link) {
        while (queuedAcks[link] < link.sent.size()) {
            byte[] bytes = link.sent[queuedAcks[link]]
            queuedAcks[link] = queuedAcks[link] + 1
            new FrameReader().feed(bytes, 0, bytes.length) { f ->
                def m = f.message()
                if (m instanceof msg_command_long) {
                    def ack = new msg_command_ack(command: m.command, result: (short) MAV_RESULT.MAV_RESULT_ACCEPTED)
                    comms.received(link.from(new FrameWriter(m.target_system, 1).write(ack)))
                }
            }
        }
    }
}
