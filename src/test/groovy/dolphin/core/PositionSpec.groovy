package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

/** Reference B.5 (WGS-84 with its test vectors) and B.4 (Area, the '^' operator). */
@Timeout(30)
class PositionSpec extends Specification {

    static final Position APDL = Position.fromDegrees(41.185781, -8.70606486, 0)
    static final Position B1 = Position.fromDegrees(41.184742, -8.704601, 0)
    static final Position B2 = Position.fromDegrees(41.186057, -8.706045, 0)
    static final Map<String, Position> P = [APDL: APDL, B1: B1, B2: B2]

    def "the WGS-84 constants are the reference's"() {
        expect:
        Wgs84.A == 6378137.0d
        Wgs84.E2 == 0.00669437999013d
    }

    def "fromDegrees stores radians and the height in metres"() {
        given:
        def p = Position.fromDegrees(41.185781, -8.70606486, 12.5)

        expect:
        Math.abs(p.lat() - 41.185781 * Math.PI / 180) < 1e-15
        Math.abs(p.lon() - -8.70606486 * Math.PI / 180) < 1e-15
        p.hae() == 12.5d
        Math.abs(p.latitudeDegrees() - 41.185781) < 1e-12
    }

    def "ECEF of APDL matches the reference vector within 1e-6"() {
        when:
        double[] e = Wgs84.toEcef(APDL.lat(), APDL.lon(), APDL.hae())

        then:
        Math.abs(e[0] - 4751642.734626d) < 1e-6
        Math.abs(e[1] - -727618.268373d) < 1e-6
        Math.abs(e[2] - 4177972.426444d) < 1e-6
    }

    @Unroll
    def "the distance #from -> #to is #metres m within 0.1 m, and the same backwards"() {
        expect:
        Math.abs(P[from].distanceTo(P[to]) - metres) < 0.1
        Math.abs(P[to].distanceTo(P[from]) - metres) < 0.1

        where:
        from   | to     || metres
        'APDL' | 'B1'   || 168.518497
        'B1'   | 'B2'   || 189.803976
        'B2'   | 'APDL' || 30.697125
    }

    @Unroll
    def "the displacement #from -> #to is #north m north and #east m east within 0.1 m"() {
        when:
        double[] ned = P[from].displacementTo(P[to])

        then:
        Math.abs(ned[0] - north) < 0.1
        Math.abs(ned[1] - east) < 0.1
        Math.abs(ned[2]) < 0.1

        where:
        from   | to     || north      | east
        'APDL' | 'B1'   || -115.3877  | 122.8176
        'B1'   | 'B2'   || 146.04161  | -121.232823
        'B2'   | 'APDL' || -30.651871 | -1.666217
    }

    @Unroll
    def "displacing #from by its displacement to #to reproduces #to within 1e-6 rad"() {
        when:
        double[] ned = P[from].displacementTo(P[to])
        def q = P[from].displace(ned[0], ned[1], ned[2])

        then:
        Math.abs(q.lat() - P[to].lat()) < 1e-6
        Math.abs(q.lon() - P[to].lon()) < 1e-6

        and: 'the height is only close: displace uses the geocentric latitude (the original quirk), tilting the frame by ~0.19°'
        Math.abs(q.hae() - P[to].hae()) < 1.0

        where:
        from   | to
        'APDL' | 'B1'
        'B1'   | 'B2'
        'B2'   | 'APDL'
        'B1'   | 'APDL'
    }

    def "a displacement of 100 m north, 50 m east and 10 m up moves a point by about that much"() {
        when:
        def q = APDL.displace(100, 50, -10)
        double[] back = APDL.displacementTo(q)

        then:
        Math.abs(APDL.distanceTo(q) - Math.sqrt(100 * 100 + 50 * 50 + 10 * 10)) < 1.0
        Math.abs(back[0] - 100) < 1.0
        Math.abs(back[1] - 50) < 1.0
        Math.abs(back[2] + 10) < 1.0
        q.lat() > APDL.lat()
        q.lon() > APDL.lon()
        q.hae() > 9 && q.hae() < 11
    }

    @Unroll
    def "ECEF -> geodetic inverts geodetic -> ECEF at #lat, #lon, #h"() {
        given:
        def p = Position.fromDegrees(lat, lon, h)

        when:
        double[] e = Wgs84.toEcef(p.lat(), p.lon(), p.hae())
        def q = Wgs84.fromEcef(e[0], e[1], e[2])

        then:
        Math.abs(q.lat() - p.lat()) < 1e-9
        Math.abs(q.lon() - p.lon()) < 1e-12
        Math.abs(q.hae() - p.hae()) < 1e-3

        where:
        lat       | lon         | h
        41.185781 | -8.70606486 | 0
        41.185781 | -8.70606486 | 1500
        -33.9     | 151.2       | 40
        0.5       | 0.5         | 0
        70        | -150        | 10000
    }

    def "heights count: straight-line ECEF distance"() {
        expect:
        Math.abs(APDL.distanceTo(Position.fromDegrees(41.185781, -8.70606486, 50)) - 50) < 1e-6
        APDL.distanceTo(APDL) == 0d
    }

    def "near is distance <= radius"() {
        expect:
        APDL.near(B2, 31)
        !APDL.near(B2, 30)
        APDL.near(B2, APDL.distanceTo(B2))
    }

    @Unroll
    def "the string form is (lat°, lon°, hae) with 6, 6 and 3 decimals, whatever the default locale (#locale)"() {
        given:
        def saved = Locale.getDefault()
        Locale.setDefault(locale)

        expect:
        Position.fromDegrees(41.185781, -8.70606486, 12.34567).toString() == '(41.185781°, -8.706065°, 12.346)'

        cleanup:
        Locale.setDefault(saved)

        where:
        locale << [Locale.ROOT, Locale.US, Locale.GERMANY, Locale.FRANCE]
    }

    def "pos ^ r is the area of radius r around pos"() {
        when:
        def area = APDL ^ 100

        then:
        area instanceof Area
        area.center() == APDL
        area.radius() == 100d
        area.contains(B2)
        !area.contains(B1)
        area.contains(APDL)
        (APDL ^ 2.5).radius() == 2.5d
    }

    def "an area contains the positions within its radius, its boundary included, heights counting"() {
        given:
        def area = new Area(APDL, APDL.distanceTo(B1))

        expect:
        area.contains(B1)
        area.contains(B2)
        !new Area(APDL, APDL.distanceTo(B1) - 0.01).contains(B1)
        !new Area(APDL, 100).contains(Position.fromDegrees(41.185781, -8.70606486, 150))
        new Area(APDL, 200).contains(Position.fromDegrees(41.185781, -8.70606486, 150))
    }

    def "an unknown position is in no area"() {
        expect:
        !new Area(APDL, 1e7).contains(null)
    }

    def "at the equator at sea level, where the first guess's height is already 0, displacing east stays on the equator"() {
        given: 'just south of the equator, at height 0: the ECEF inversion once kept its crude first guess there'
        def p = Position.fromDegrees(-9e-7, 0.0002246, 0)

        when:
        def q = p.displace(0, 5, 0)
        def ned = p.displacementTo(q)

        then:
        Math.abs(ned[0]) < 0.01
        Math.abs(ned[1] - 5) < 0.01
        Math.abs(Wgs84.fromEcef(*Wgs84.toEcef(p.lat(), p.lon(), 0)).lat() - p.lat()) < 1e-12
    }
}
