package dolphin.mavlink

import com.MAVLink.common.msg_attitude
import com.MAVLink.common.msg_command_long
import com.MAVLink.common.msg_system_time
import com.MAVLink.enums.MAV_AUTOPILOT
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_TYPE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.ManualClock
import dolphin.core.VehicleEvent
import dolphin.mavlink.codec.FrameWriter
import dolphin.mavlink.codec.SigningKey
import java.time.Duration
import spock.lang.Specification

import static dolphin.core.VehicleEvent.EventKind.CONTACT_LOST
import static dolphin.core.VehicleEvent.EventKind.LINK_CHANGED

/**
 * One vehicle heard on a radio and an LTE link (docs/mavlink.md, "One vehicle on two links"), on a
 * manual clock with fake links: the frames of each link are delivered with its own delay.
 */
class VehicleOnTwoLinksSpec extends Specification {

    static final String RADIO = 'serial:/dev/ttyUSB0:57600'
    static final String LTE = 'udpin:0.0.0.0:14560'

    ManualClock clock = new ManualClock()
    FakeLink radio = new FakeLink(0, RADIO)
    FakeLink lte = new FakeLink(1, LTE)
    MAVLinkCommunications comms
    List<VehicleEvent> events = []
    /** time_boot_ms of every ATTITUDE and SYSTEM_TIME processed, in the order processed. */
    List<Long> attitudes = []
    List<Long> systemTimes = []
    /** Frames on their way: [due nanos, order, link, bytes]. */
    PriorityQueue<List> air = new PriorityQueue<>({ a, b -> a[0] <=> b[0] ?: a[1] <=> b[1] } as Comparator)
    long order
    Random random = new Random(7)

    def setup() {
        start(MAVLinkConfig.of(RADIO, LTE))
    }

    void start(MAVLinkConfig config) {
        comms = new MAVLinkCommunications(config, clock)
        comms.attachForSpecs([radio, lte])
        comms.addVehicleEventListener { events << it }
        comms.messageHandler().on(msg_attitude) { n, m -> attitudes << m.time_boot_ms }
        comms.messageHandler().on(msg_system_time) { n, m -> systemTimes << m.time_boot_ms }
    }

    def "one vehicle on a radio and an LTE link is one node: each frame is processed once, whichever link brings it first"() {
        given: 'a copter that sends every frame on both links (the LTE link from lteFromMs on), and SYSTEM_TIME on the LTE link alone from 2 s on'
        def copter = new FrameWriter(1, 1)

        when:
        run(10) { long ms ->
            if (ms < 9000) {
                stream(copter, ms, ms >= lteFromMs ? [(radio): radioMs, (lte): lteMs] : [(radio): radioMs])
            }
            if (ms >= 2000 && ms < 9000) {
                transmit(copter.write(new msg_system_time(time_boot_ms: 1000 + ms, time_unix_usec: 1_700_000_000_000_000L + ms * 1000)),
                        [(lte): lteMs])
            }
        }
        def node = comms.node('1')

        then: 'one vehicle, heard on both links, the one whose heartbeat came first first'
        comms.nodes()*.id == ['1']
        node.getLinks() == [this."$discoveredOn", this."$joined"]
        events*.kind == [LINK_CHANGED]
        events[0].text == "also heard on ${this."$joined"}, the same frames as on ${this."$discoveredOn"}"

        and: 'every ATTITUDE processed once (as it comes: a frame held while the links were told apart comes later on the slower one); the frames only the LTE link carries processed too'
        attitudes.size() == 90
        attitudes.toSet() == (0..<90).collect { 1000L + it * 100 }.toSet()
        systemTimes == (20..<90).collect { 1000L + it * 100 }

        and: "the slower link's copies dropped as its duplicates, and as nothing else"
        node.duplicatesOn(this."$slower") >= 75
        node.duplicatesOn(this."$faster") == 0
        comms.drops().frames() == 0

        where: 'the candidate link slower than the known one, or faster'
        radioMs | lteMs | lteFromMs || discoveredOn | joined  | slower  | faster
        0       | 200   | 0         || 'radio'      | 'lte'   | 'lte'   | 'radio'
        300     | 0     | 0         || 'lte'        | 'radio' | 'radio' | 'lte'
        300     | 0     | 1000      || 'radio'      | 'lte'   | 'radio' | 'lte'
    }

    def "two vehicles with system id 1, one on each link, are two nodes once 4 s pass without a frame with a time in common"() {
        given: 'two copters of one fleet, started together: the same heartbeats with the same sequence numbers, other boot times'
        def first = new FrameWriter(1, 1)
        def second = new FrameWriter(1, 1)

        when:
        run(3.8) { long ms ->
            stream(first, ms, [(radio): 0])
            stream(second, ms, [(lte): 0], 6000)
        }

        then: 'the second is not yet told apart'
        comms.nodes()*.id == ['1']

        when:
        run(0.4) { long ms ->
            stream(first, ms, [(radio): 0])
            stream(second, ms, [(lte): 0], 6000)
        }

        then: 'it is another vehicle, 1@2, on the LTE link alone; the first kept the radio'
        comms.nodes()*.id == ['1', '1@2']
        comms.node('1').getLinks() == [radio]
        comms.node('1@2').getLinks() == [lte]
        comms.node('1@2').modeName == 'STABILIZE'
        events.empty

        when: 'each gets a command'
        radio.sent.clear()
        lte.sent.clear()
        command('1')
        command('1@2')

        then: 'through its own link'
        setModes(radio) == 1
        setModes(lte) == 1
    }

    def "a vehicle's sends go through the link it was discovered on, then through the other when that falls silent for 1.5 s, and stay there"() {
        given:
        def copter = new FrameWriter(1, 1)
        run(3) { long ms -> stream(copter, ms, [(radio): 0, (lte): 150]) }

        when:
        radio.sent.clear()
        lte.sent.clear()
        command('1')

        then: 'through the radio'
        setModes(radio) == 1
        setModes(lte) == 0

        when: 'the radio falls silent'
        run(1.4) { long ms -> stream(copter, ms, [(lte): 150]) }

        then: 'no change before 1.5 s'
        events*.kind == [LINK_CHANGED]

        when:
        run(0.3) { long ms -> stream(copter, ms, [(lte): 150]) }
        radio.sent.clear()
        lte.sent.clear()
        command('1')

        then: 'one line, and the command goes through the LTE link'
        events*.kind == [LINK_CHANGED, LINK_CHANGED]
        events[1].text ==~ /now through ${LTE}: ${RADIO} silent 1\.[5-6] s/
        setModes(lte) == 1
        setModes(radio) == 0

        when: 'the radio is back, faster than the LTE link'
        run(10) { long ms -> stream(copter, ms, [(radio): 0, (lte): 150]) }

        then: 'the path stays on the LTE link, which still works'
        events.size() == 2
        comms.node('1').getLink() == lte

        and: 'every ATTITUDE was processed once, from whichever link brought it first'
        attitudes.size() == 147
        attitudes.toSet() == (0..<147).collect { 1000L + it * 100 }.toSet()
    }

    def "two good links, each sometimes first, each losing a fifth of the frames: the path never changes and no frame is processed twice"() {
        given:
        def copter = new FrameWriter(1, 1)
        Set<Long> delivered = []

        when:
        run(60) { long ms ->
            def routes = [:]
            if (random.nextDouble() > 0.2) {
                routes[radio] = random.nextInt(300)
            }
            if (random.nextDouble() > 0.2) {
                routes[lte] = random.nextInt(300)
            }
            if (ms < 59500) {
                stream(copter, ms, routes)
                if (routes) {
                    delivered << 1000L + ms
                }
            }
        }

        then: 'one line, when the LTE link joined'
        events*.kind == [LINK_CHANGED]
        comms.node('1').getLink() == radio

        and: 'after the first seconds, when the LTE link was told apart, every ATTITUDE either link brought processed once'
        attitudes.toUnique().size() == attitudes.size()
        attitudes.findAll { it >= 3000 }.toSet() == delivered.findAll { it >= 3000 }
    }

    def "the vehicle stays in contact while either link brings it, and loses it when both fall silent"() {
        given:
        def copter = new FrameWriter(1, 1)
        run(3) { long ms -> stream(copter, ms, [(radio): 0, (lte): 100]) }

        when: 'the radio falls silent for 10 s'
        run(10) { long ms -> stream(copter, ms, [(lte): 100]) }

        then:
        !events*.kind.contains(CONTACT_LOST)
        comms.node('1').silence().empty

        when: 'the LTE link too'
        run(3.5) { }

        then:
        events*.kind.contains(CONTACT_LOST)
        comms.node('1').silence().present
    }

    def "a link heard once and then silent for 4 s is forgotten: when it brings the vehicle again it is told apart afresh"() {
        given: 'the LTE link brings one ATTITUDE of the copter at 0.5 s, then nothing until 10 s'
        def copter = new FrameWriter(1, 1)
        run(10) { long ms ->
            stream(copter, ms, ms == 500 ? [(radio): 0, (lte): 50] : [(radio): 0])
        }

        when:
        run(3) { long ms -> stream(copter, ms, [(radio): 0, (lte): 50]) }

        then: 'the same vehicle, not another one for having taken longer than 4 s'
        comms.nodes()*.id == ['1']
        comms.node('1').getLinks() == [radio, lte]
    }

    def "a link that first brings the vehicle while its other link is silent has nothing to compare it with: another vehicle, 1@2"() {
        given: 'the copter on the radio, which falls silent at 3 s; the LTE link comes up at 5 s'
        def copter = new FrameWriter(1, 1)
        run(3) { long ms -> stream(copter, ms, [(radio): 0]) }
        run(2) { }

        when:
        run(4.5) { long ms -> stream(copter, ms, [(lte): 0]) }

        then:
        comms.nodes()*.id == ['1', '1@2']
        comms.node('1@2').getLinks() == [lte]
    }

    def "signed frames on both links: the copies are duplicates, not replays"() {
        given:
        def key = SigningKey.fromPassphrase('two links')
        start(MAVLinkConfig.of(RADIO, LTE).withSigningKey(key))
        def copter = new FrameWriter(1, 1, key, 0)

        when:
        run(5) { long ms -> stream(copter, ms, [(radio): 0, (lte): 50]) }

        then:
        comms.nodes()*.id == ['1']
        comms.drops().frames() == 0
        comms.node('1').duplicatesOn(lte) > 30
    }

    /** Sends the vehicle a COMMAND_LONG DO_SET_MODE, once: where it goes shows the vehicle's path. */
    void command(String id) {
        comms.send(comms.node(id), new msg_command_long(command: MAV_CMD.MAV_CMD_DO_SET_MODE, target_system: 1, target_component: 1))
        comms.runDue()
    }

    /** The DO_SET_MODE commands sent on a link (the telemetry requests are COMMAND_LONGs too). */
    int setModes(FakeLink link) {
        link.sentFrames().count { it.msgid == msg_command_long.MAVLINK_MSG_ID_COMMAND_LONG && it.message().command == MAV_CMD.MAV_CMD_DO_SET_MODE }
    }

    /** What a copter sends at {@code ms}: an ATTITUDE every 100 ms, a HEARTBEAT every second, on each link of {@code routes}. */
    void stream(FrameWriter copter, long ms, Map<FakeLink, Integer> routes, long bootMs = 1000) {
        if (ms % 1000 == 0) {
            transmit(copter.write(new msg_heartbeat(type: MAV_TYPE.MAV_TYPE_QUADROTOR, autopilot: MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA,
                    custom_mode: 0, system_status: 3, mavlink_version: 3)), routes)
        }
        transmit(copter.write(new msg_attitude(time_boot_ms: bootMs + ms, roll: (ms % 700) as float)), routes)
    }

    /** One frame, sent on each link of {@code routes} to arrive after that link's delay in ms. */
    void transmit(byte[] frame, Map<FakeLink, Integer> routes) {
        routes.each { link, delayMs -> air.add([clock.nanoTime() + delayMs * 1_000_000L, order++, link, frame]) }
    }

    /** Runs the clock for {@code seconds} in 10 ms steps: {@code every100ms} sends, each frame arrives when due. */
    void run(double seconds, Closure every100ms) {
        long end = clock.nanoTime() + Math.round(seconds * 1e9)
        while (clock.nanoTime() < end) {
            long ms = clock.nanoTime().intdiv(1_000_000L)
            if (ms % 100 == 0) {
                every100ms(ms)
            }
            while (!air.isEmpty() && air.peek()[0] <= clock.nanoTime()) {
                def due = air.poll()
                comms.received(due[2].datagram(due[3]))
            }
            comms.runDue()
            clock.advance(Duration.ofMillis(10))
        }
        comms.runDue()
    }
}
