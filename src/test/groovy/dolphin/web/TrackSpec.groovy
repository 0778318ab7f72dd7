package dolphin.web

import dolphin.core.Position
import spock.lang.Specification

class TrackSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    def "a point each time the vehicle has moved 2 m; a vehicle standing still adds none"() {
        given:
        def track = new Track()

        when:
        track.add(HOME)
        track.add(HOME.displace(1, 0, 0))
        track.add(HOME.displace(1.9, 0, -30))   // climbing in place is not a horizontal move
        track.add(HOME.displace(2.5, 0, 0))

        then:
        track.size() == 2
        track.points()[1][0] > track.points()[0][0]
    }

    def "a long track keeps its ends and its shape in bounded memory"() {
        given:
        def track = new Track()

        when:
        (0..<5000).each { track.add(HOME.displace(it * 3, (it % 100) * 3, 0)) }

        then:
        track.size() < Track.MAX_POINTS
        track.size() > Track.MAX_POINTS / 4
        track.points()[0] == [HOME.latitudeDegrees(), HOME.longitudeDegrees()].collect { Math.round(it * 1e7) / 1e7 }
        def last = HOME.displace(4999 * 3, 99 * 3, 0)
        Math.abs((track.points()[-1][0] as double) - last.latitudeDegrees()) < 1e-6
    }
}
