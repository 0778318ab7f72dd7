package dolphin.mavlink

import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.ManualClock
import java.time.Duration
import spock.lang.Specification

/** Asking what a vehicle offers until it answers, on a manual clock: the asks a lost reply costs. */
class CapabilityRequestsSpec extends Specification {

    ManualClock clock = new ManualClock()
    List<Double> asks = []
    CapabilityRequests requests = new CapabilityRequests({ node -> asks << clock.seconds() } as CapabilityRequests.Asker)
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', null, null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)

    private void heartbeat() {
        node.update { it.withHeartbeat(new msg_heartbeat(), clock.nanoTime()) }
    }

    /** Runs the communications thread's checks every 250 ms for {@code seconds}, the vehicle heard all along. */
    private void run(double seconds) {
        for (int i = 0; i < seconds * 4; i++) {
            clock.advance(Duration.ofMillis(250))
            heartbeat()
            requests.check(clock.nanoTime())
        }
    }

    def "an unanswered ask is repeated after 1 s, then 2, 4 and 8 s, and never again once the vehicle answered"() {
        given:
        heartbeat()

        when:
        requests.ask(node, clock.nanoTime())
        run(20)

        then:
        asks == [0.0d, 1.0d, 3.0d, 7.0d, 15.0d]
        node.capabilityAsks() == 5

        when:
        node.capabilities(0x1000)
        requests.answered(node)
        run(30)

        then:
        asks.size() == 5
        node.capabilityAsks() == 0
    }

    def "a slow link waits three of its round-trip timeouts before asking again"() {
        given:
        heartbeat()
        4.times { node.roundTrip().sample(600_000_000L) }   // a radio under load: 0.6 s round trips

        when:
        requests.ask(node, clock.nanoTime())
        run(6)

        then: 'three timeouts (0.6 s plus four deviations: 1.1 s) instead of 1 s'
        asks.size() == 2
        asks[1] >= 2.0d && asks[1] <= 3.5d
    }

    def "a vehicle that is lost is not asked; one heard again is asked at once, though it answered before"() {
        given:
        heartbeat()
        requests.ask(node, clock.nanoTime())

        when: 'silent past its connection timeout, then 10 s more of checks'
        clock.advance(Duration.ofSeconds((long) node.getConnectionTimeout() + 1))
        for (int i = 0; i < 40; i++) {
            clock.advance(Duration.ofMillis(250))
            requests.check(clock.nanoTime())
        }

        then:
        !node.isConnected()
        asks == [0.0d]

        when: 'it answered long ago, and comes back'
        node.capabilities(0)
        requests.answered(node)
        heartbeat()
        requests.ask(node, clock.nanoTime())

        then:
        asks == [0.0d, clock.seconds()]
    }

    def "a transfer's hurry asks at once, but not twice within the link's round-trip timeout, and never an answered vehicle"() {
        given:
        heartbeat()
        4.times { node.roundTrip().sample(200_000_000L) }
        requests.ask(node, clock.nanoTime())

        when: 'right after the first ask: it is on its way'
        clock.advance(Duration.ofMillis(100))
        requests.hurry(node, clock.nanoTime())

        then:
        asks.size() == 1

        when: 'a round-trip timeout (0.37 s) after it'
        clock.advance(Duration.ofMillis(300))
        requests.hurry(node, clock.nanoTime())

        then:
        asks.size() == 2

        when:
        requests.answered(node)
        clock.advance(Duration.ofSeconds(1))
        requests.hurry(node, clock.nanoTime())

        then:
        asks.size() == 2
    }
}
