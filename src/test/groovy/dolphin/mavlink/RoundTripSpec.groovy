package dolphin.mavlink

import java.time.Duration
import spock.lang.Specification
import spock.lang.Unroll

/** RoundTrip, RFC 6298's estimator, and LinkTimeouts, the retransmission timeout derived from it with back-off and bounds. */
class RoundTripSpec extends Specification {

    static long ms(double millis) { Math.round(millis * 1e6) }

    def "before any sample the timeout is the initial one; the first sample sets the round trip and half of it as deviation"() {
        given:
        def rtt = new RoundTrip()

        expect:
        rtt.timeoutNanos(ms(1500)) == ms(1500)
        rtt.smoothedNanos() == -1
        rtt.samples() == 0

        when:
        rtt.sample(ms(100))

        then: 'SRTT = R, RTTVAR = R / 2, RTO = SRTT + 4 RTTVAR'
        rtt.smoothedNanos() == ms(100)
        rtt.deviationNanos() == ms(50)
        rtt.timeoutNanos(ms(1500)) == ms(300)
        rtt.samples() == 1
    }

    def "later samples move the round trip by 1/8 and the deviation by 1/4 of the difference; negative samples are ignored"() {
        given:
        def rtt = new RoundTrip()
        rtt.sample(ms(100))

        when:
        rtt.sample(ms(200))

        then: 'RTTVAR = 3/4 50 + 1/4 |100 - 200| = 62.5; SRTT = 7/8 100 + 1/8 200 = 112.5'
        rtt.deviationNanos() == ms(62.5)
        rtt.smoothedNanos() == ms(112.5)
        rtt.timeoutNanos(0) == ms(112.5 + 250)

        when:
        rtt.sample(-5)

        then:
        rtt.samples() == 2
    }

    def "a steady link converges to its round trip, the deviation to the clock granularity (1 ms)"() {
        given:
        def rtt = new RoundTrip()

        when:
        60.times { rtt.sample(ms(80)) }

        then:
        rtt.smoothedNanos() == ms(80)
        rtt.deviationNanos() < ms(0.01)
        rtt.timeoutNanos(0) == ms(81)
    }

    @Unroll
    def "LinkTimeouts: #rounds, #backoffs back-offs -> #expected ms"() {
        given:
        def rtt = new RoundTrip()
        samples.each { rtt.sample(ms(it)) }

        expect:
        LinkTimeouts.DEFAULT.timeout(rtt, backoffs) == Duration.ofNanos(ms(expected))

        where:
        samples      | backoffs || expected
        []           | 0        || 1500      // nothing measured: the longest
        []           | 3        || 1500
        [100]        | 0        || 300       // 100 + 4 x 50
        [100]        | 1        || 600       // doubled per timeout in a row
        [100]        | 2        || 1200
        [100]        | 3        || 1500      // clamped to the longest
        [100] * 60   | 0        || 101       // a steady link: the round trip and 1 ms
        [100] * 60   | 4        || 1500
        [5] * 60     | 0        || 50        // never shorter than the shortest
        [5] * 60     | 1        || 100       // backing off from the shortest, not from 6 ms
        [5] * 60     | 4        || 800
        [5] * 60     | 5        || 1500
        rounds = samples ? "${samples.size()} samples of ${samples[0]} ms" : 'no sample'
    }

    @Unroll
    def "LinkTimeouts refuses bounds that do not nest: #message"() {
        when:
        new LinkTimeouts(Duration.ofMillis(min), Duration.ofMillis(max), Duration.ofMillis(giveUp))

        then:
        def e = thrown(IllegalArgumentException)
        e.message.startsWith(message)

        where:
        min | max  | giveUp || message
        0   | 1500 | 10000  || 'the shortest retransmission timeout must be positive'
        100 | 50   | 10000  || 'the longest retransmission timeout (PT0.05S) must be at least the shortest (PT0.1S)'
        50  | 1500 | 1000   || 'the time without progress before giving up (PT1S) must be at least the longest retransmission timeout (PT1.5S)'
    }
}
