package dolphin.mavlink

import spock.lang.Specification

/** Bytes per second over the last five whole seconds of clock time, in clock nanoseconds: no clock, no thread. */
class ByteRateSpec extends Specification {

    static long at(double seconds) { Math.round(seconds * 1e9) }

    /** 1000 bytes every half second from {@code from} up to, not including, {@code to}. */
    static void steady(ByteRate rate, double from, double to) {
        for (double t = from; t < to; t += 0.5) {
            rate.add(at(t), 1000)
        }
    }

    def "a steady 2000 B/s reads 2000 B/s once a whole second has passed, and nothing in the first"() {
        given:
        def rate = new ByteRate(at(0))

        when:
        steady(rate, 0, 0.9)

        then: 'no whole second yet'
        rate.perSecond(at(0.9)) == 0d

        when:
        steady(rate, 1, 2.5)

        then: 'the mean of the whole seconds 0 and 1; the second going on does not count'
        rate.perSecond(at(2.5)) == 2000d

        when:
        steady(rate, 2.5, 30)

        then:
        rate.perSecond(at(29.9)) == 2000d
        rate.total() == 60 * 1000
    }

    def "when the link falls quiet its rate falls over five seconds to nothing"() {
        given:
        def rate = new ByteRate(at(0))
        steady(rate, 0, 10)

        expect: 'seconds 5 to 9 full, then 10 and 11 empty, then only empty ones'
        rate.perSecond(at(10.1)) == 2000d
        rate.perSecond(at(12.0)) == 1200d
        rate.perSecond(at(15.0)) == 0d
        rate.perSecond(at(400)) == 0d
    }

    def "bytes after a long silence are averaged with the empty seconds before them, not with the old ones"() {
        given:
        def rate = new ByteRate(at(0))
        steady(rate, 0, 3)

        when:
        rate.add(at(100.2), 500)

        then:
        rate.perSecond(at(101.5)) == 100d
        rate.total() == 6500
    }

    def "a clock whose nanoseconds start below zero (System.nanoTime may) is read the same"() {
        given:
        def rate = new ByteRate(at(-7.5))

        when:
        steady(rate, -7.5, 3)

        then:
        rate.perSecond(at(3)) == 2000d
    }
}
