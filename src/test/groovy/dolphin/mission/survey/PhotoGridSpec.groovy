package dolphin.mission.survey

import spock.lang.Specification

/** QGroundControl's CameraCalc (docs/qgc-surveys.md §1) with the two cameras of the corpus, and the camera list. */
class PhotoGridSpec extends Specification {

    static final Camera GOPRO = Cameras.named('GoPro Hero 4').get()
    static final Camera CUSTOM = new Camera('Custom Camera', 12.8, 9.6, 5472, 3648, 8.14, 0, false)

    static boolean close(double a, double b, double tolerance) { Math.abs(a - b) <= tolerance }

    def "a GoPro Hero 4 at 100 m with 80/80 % overlap: G 5.17617 cm/px, side 41.4094 m, frontal 31.0570 m"() {
        when:
        PhotoGrid g = PhotoGrid.atAltitude(GOPRO, true, 100, 80, 80)

        then:
        close(g.gsd(), 5.176174496644295, 1e-12)
        close(g.footprintSide(), 207.0469798657718, 1e-9)
        close(g.footprintFrontal(), 155.28523489932886, 1e-9)
        close(g.spacing(), 41.40939597315436, 1e-9) // AdjustedFootprintSide of qgc_survey.plan
        close(g.triggerDistance(), 31.057046979865774, 1e-9) // AdjustedFootprintFrontal
        g.valueSetIsDistance() && !g.manual()
    }

    def "the custom 12.8 mm / 5472 px / 8.14 mm camera at 30 m, 70 % front and 80 % side: 0.862106 cm/px, 9.434889 m both ways"() {
        when:
        PhotoGrid g = PhotoGrid.atAltitude(CUSTOM, true, 30, 70, 80)

        then:
        close(g.gsd(), 0.86210612526402, 1e-12)
        close(g.spacing(), 9.434889434889433, 1e-9)
        close(g.triggerDistance(), 9.434889434889433, 1e-9)
    }

    def "set by ground sample distance the altitude follows, and portrait swaps the footprints"() {
        when:
        PhotoGrid byGsd = PhotoGrid.atGsd(GOPRO, false, 5.176174496644295, 80, 80)

        then:
        close(byGsd.altitude(), 100, 1e-9)
        !byGsd.valueSetIsDistance()
        close(byGsd.footprintSide(), 155.28523489932886, 1e-9)
        close(byGsd.footprintFrontal(), 207.0469798657718, 1e-9)
    }

    def "a manual grid takes the three numbers as they are and has no camera figures"() {
        when:
        PhotoGrid g = PhotoGrid.manual(50, 25, 0)

        then:
        g.manual() && g.camera() == null
        [g.altitude(), g.spacing(), g.triggerDistance()] == [50d, 25d, 0d]
        [g.gsd(), g.frontOverlap(), g.sideOverlap(), g.footprintSide(), g.footprintFrontal()].every { Double.isNaN(it) }
    }

    def "#which overlap #value % is refused"() {
        when:
        PhotoGrid.atAltitude(GOPRO, true, 100, which == 'front' ? value : 80, which == 'side' ? value : 80)

        then:
        IllegalArgumentException e = thrown()
        e.message == "the $which overlap must be above 0 % and below 100 %, got ${value as int} %"

        where:
        which   | value
        'front' | 0
        'front' | 100
        'side'  | 0
        'side'  | 100
    }

    def "camera numbers must be real and above 0: #message"() {
        when:
        new Camera(*args)

        then:
        IllegalArgumentException e = thrown()
        e.message == message

        where:
        args                                                    | message
        ['X', 6.17, 4.55, 4000, 3000, 0, 0, false]              | "camera 'X': the focal length must be above 0 mm, got 0"
        ['X', Double.NaN, 4.55, 4000, 3000, 2.98, 0, false]     | "camera 'X': the sensor width must be above 0 mm, got NaN"
        ['X', 6.17, -1, 4000, 3000, 2.98, 0, false]             | "camera 'X': the sensor height must be above 0 mm, got -1"
        ['X', 6.17, 4.55, 0, 3000, 2.98, 0, false]              | "camera 'X': the image width must be above 0 px, got 0"
        ['X', 6.17, 4.55, 4000, 3000, 2.98, -1, false]          | "camera 'X': the minimum trigger interval must be 0 s or more, got -1"
        [' ', 6.17, 4.55, 4000, 3000, 2.98, 0, false]           | 'a camera needs a name, got a blank one'
    }

    def "grid numbers must be usable: #message"() {
        when:
        make()

        then:
        IllegalArgumentException e = thrown()
        e.message == message

        where:
        make                                                   | message
        ({ PhotoGrid.atAltitude(GOPRO, true, 0, 80, 80) })     | 'the altitude (distance to the surface) must be above 0 m, got 0'
        ({ PhotoGrid.atGsd(GOPRO, true, Double.NaN, 80, 80) }) | 'the ground sample distance must be above 0 cm/px, got NaN'
        ({ PhotoGrid.manual(50, 0, 25) })                      | 'the transect spacing must be above 0 m, got 0'
        ({ PhotoGrid.manual(50, 25, -1) })                     | 'the trigger distance must be 0 m (no photos) or more, got -1'
    }

    def "QGroundControl's 35 named cameras, found by name case aside, with near names for a typo"() {
        expect:
        Cameras.all().size() == 35
        Cameras.all()*.name().toSet().size() == 35
        Cameras.named('gopro hero 4').get() == GOPRO
        GOPRO.sensorWidth() == 6.17 && GOPRO.focalLength() == 2.98 && GOPRO.imageWidth() == 4000
        Cameras.named('Yuneec E90').get().fixedOrientation()
        !Cameras.named('Hasselblad').isPresent()
        Cameras.closest('GoPro Hero4', 3) == ['GoPro Hero 4']
        Cameras.closest('a6000', 5) == ['Sony a6000 16mm', 'Sony a6000 35mm']
        Cameras.closest('zzzzzz', 3).isEmpty()
    }
}
