package dolphin.mission.survey

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.mission.model.MissionItem
import spock.lang.Specification

import static dolphin.mission.survey.SurveyFixtures.*
import static dolphin.mission.survey.TransectPoint.PointKind.*

/**
 * Corridor scans (docs/qgc-surveys.md §3.1) along a polyline 200 m east then 200 m north, and
 * structure scans (§3.2) round a 20 m square building, worked out by hand.
 */
class CorridorAndStructureSpec extends Specification {

    static final int WP = MAV_CMD.MAV_CMD_NAV_WAYPOINT, TRIG = MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST
    static final List ELL = outline([[0, 0], [200, 0], [200, 200]])

    static CorridorScan corridor(TransectOptions options) {
        new CorridorScan('corridorScan', ELL, 60, PhotoGrid.manual(50, 20, 25), EntryCorner.TOP_LEFT, options)
    }

    def "a corridor 60 m wide at 20 m spacing: the polyline offset 20 m left, along it, and 20 m right, mitred at the bend"() {
        when:
        CorridorScan c = corridor(TransectOptions.defaults().withTurnaround(0))
        List<List<List<Double>>> t = c.transects().collect { it.collect { metres(it) } }

        then:
        c.transects().size() == 3
        [t[0], [[0, 20], [180, 20], [180, 200]]].transpose().every { a, b -> near(a, b) }
        [t[1], [[200, 200], [200, 0], [0, 0]]].transpose().every { a, b -> near(a, b) } // the lawnmower reverses it
        [t[2], [[0, -20], [220, -20], [220, 200]]].transpose().every { a, b -> near(a, b) }
        c.transects()*.collect { it.kind() } == [[ENTRY, INTERIOR, EXIT]] * 3 // current QGC relabels the reversed one
        c.qgcType() == 'CorridorScan'
        !c.closedOutline()
    }

    def "corridor items: a trigger start at each entry, a stop at each exit"() {
        expect:
        corridor(TransectOptions.defaults().withTurnaround(0).withTriggerInTurnarounds(false)).items(1)*.command() ==
                [WP, TRIG, WP, WP, TRIG] * 3
    }

    def "corridor turnarounds continue the first and last legs outwards"() {
        when:
        CorridorScan c = corridor(TransectOptions.defaults())

        then:
        near(metres(c.path()[0]), [-10, 20])
        near(metres(c.transects()[0].last()), [180, 210])
        c.transects()[0]*.kind() == [TURNAROUND, ENTRY, INTERIOR, EXIT, TURNAROUND]
    }

    def "the intermediate generation keeps the labels of a reversed corridor transect: its camera starts at the far end"() {
        expect:
        corridor(TransectOptions.defaults().withTurnaround(0).withEmission(Emission.CURRENT_NO_LABEL_SWAP))
                .transects()[1]*.kind() == [EXIT, INTERIOR, ENTRY]
    }

    def "a corridor of width 0 is one line along the polyline"() {
        expect:
        new CorridorScan('c', ELL, 0, PhotoGrid.manual(50, 20, 25), EntryCorner.TOP_LEFT, TransectOptions.defaults().withTurnaround(0))
                .path().collect { metres(it) }.withIndex().every { p, i -> near(p, [[0, 0], [200, 0], [200, 200]][i]) }
    }

    static final List BUILDING = outline([[0, 0], [20, 0], [20, -20], [0, -20]])

    static StructureScan structure(boolean fromTop, List polygon = BUILDING) {
        new StructureScan('structureScan', polygon, PhotoGrid.manual(10, 8, 5), 30, 10, 40, fromTop, 0)
    }

    def "a structure scan from #direction: (N + 3)·L + 4 items, layers half a layer inside the band"() {
        when:
        StructureScan s = structure(fromTop)
        List<MissionItem> items = s.items(1)
        List<MissionItem> wps = items.findAll { it.command() == WP }

        then:
        s.layers() == 4 // ceil((30 - 10) / 5)
        items.size() == (4 + 3) * 4 + 4
        (0..3).collect { s.layerAltitude(it) } == altitudes
        wps*.z() == [40f] + altitudes.collectMany { [it as float] * 5 } + [40f]
        wps*.frame().unique() == [MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT]
        // ArduPilot's region of interest instead of QGC's WPNEXT_OFFSET: the centre, half-way up the 10 to 30 m band
        items[1].command() == MAV_CMD.MAV_CMD_DO_SET_ROI_LOCATION && items[1].z() == 20f
        items[1].frame() == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
        items[-2].command() == MAV_CMD.MAV_CMD_DO_SET_ROI_NONE
        items.findAll { it.command() == TRIG }.collect { [it.param1(), it.param3()] } == [[8f, 1f], [0f, 0f]] * 4
        items[2..4]*.command() == [WP, TRIG, WP]

        where:
        direction | fromTop | altitudes
        'the top' | true    | [27.5d, 22.5d, 17.5d, 12.5d]
        'below'   | false   | [12.5d, 17.5d, 22.5d, 27.5d]
    }

    def "the structure polygon is made clockwise, so the ring lies 10 m outside the walls whichever way it was drawn"() {
        expect:
        [BUILDING, BUILDING.reverse()].every { polygon ->
            structure(true, polygon).flightPolygon().collect { metres(it) }
                    .every { Math.abs(Math.abs(it[0] - 10) - 20) < 0.01 && Math.abs(Math.abs(it[1] + 10) - 20) < 0.01 }
        }
    }

    def "structure footprints: photos every 8 m round each 160 m ring, on the wall 10 m inside it"() {
        given:
        PhotoGrid camera = PhotoGrid.atAltitude(Cameras.named('Sony a6000 35mm').get(), true, 10, 70, 70)
        StructureScan s = new StructureScan('structureScan', BUILDING, camera, 30, 10, 40, true, 0)
        List<Double> corner = metres(s.footprints()[0][0])

        expect:
        s.footprints().size() == s.layers() * (int) (160 / camera.spacing() + 1)
        s.footprints()[0][0].hae() == s.layerAltitude(0) + camera.footprintFrontal() / 2
        Math.abs(corner[1]) < 0.01 // the first photo faces the north wall
    }
}
