package dolphin.sim

import dolphin.core.SystemClock
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import spock.lang.Specification
import spock.lang.Timeout
import spock.util.concurrent.PollingConditions

/**
 * A fleet larger than one MAVLink network (255 systems) is split over several links in blocks,
 * system ids starting again on each; the ground station keeps same ids on different links apart.
 */
class FleetLinksSpec extends Specification {

    static List<InetSocketAddress> ports(int n) {
        (1..n).collect { new InetSocketAddress('127.0.0.1', 14000 + it) }
    }

    static SimFleet.Config config(int count, int links, int firstSysid = 1) {
        SimFleet.Config.of(count, VehicleKind.COPTER, ports(links)).withFirstSysid(firstSysid)
    }

    def "#count vehicles over #links link(s) from id #first: #perLink per link, ids #ids"() {
        when:
        def c = config(count, links, first)

        then:
        c.perLink() == perLink
        (0..<count).collect { c.linkOf(it) }.unique() == (0..<links).toList()
        [c.sysidOf(0), c.sysidOf(perLink - 1), c.sysidOf(count - 1)] == ids
        c.highestSysid() == ids.max()

        where:
        count | links | first || perLink | ids
        4     | 2     | 1     || 2       | [1, 2, 4]
        255   | 1     | 1     || 255     | [1, 255, 255]
        300   | 2     | 1     || 150     | [1, 150, 150]
        1000  | 4     | 1     || 250     | [1, 250, 250]
        250   | 2     | 6     || 125     | [6, 130, 255]
    }

    def "within a link no two vehicles share a system id"() {
        given:
        def c = config(1000, 4)

        expect:
        (0..<1000).groupBy { c.linkOf(it) }.values().every { block -> block.collect { c.sysidOf(it) }.toUnique().size() == block.size() }
    }

    def "too many vehicles for the links is refused, saying how many links are needed"() {
        when:
        config(count, links, first)

        then:
        def e = thrown(IllegalArgumentException)
        e.message == message

        where:
        count | links | first || message
        256   | 1     | 1     || '256 vehicles from system id 1 need at least 2 links (255 system ids per link), got 1'
        1000  | 3     | 1     || '1000 vehicles from system id 1 need at least 4 links (255 system ids per link), got 3'
        60    | 1     | 200   || '60 vehicles from system id 200 need at least 2 links (56 system ids per link), got 1'
    }

    @Timeout(60)
    def "300 simulated vehicles on two links are 300 vehicles to the ground station: plain ids where unique, ID@LINK else"() {
        given:
        def clock = new SystemClock(10)
        def comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0', 'udpin:127.0.0.1:0'), clock)
        comms.start()
        def gcs = comms.links().collect { new InetSocketAddress('127.0.0.1', it.localPort()) }
        def fleet = new SimFleet(SimFleet.Config.of(300, VehicleKind.COPTER, gcs), clock)
        fleet.start()

        expect:
        new PollingConditions(timeout: 30, delay: 0.1).eventually {
            assert comms.nodes().size() == 300
            assert comms.nodes().every { it.state().batteryPercent() == 100 }
        }
        def ids = comms.nodes()*.id
        ids.toUnique().size() == 300
        (1..150).every { id -> ids.contains("$id".toString()) && ids.count { it ==~ /$id@[12]/ } == 1 }
        comms.nodes().groupBy { it.link.index() }.collectEntries { k, v -> [k, v*.mavLinkId.toSorted()] } ==
                [0: (1..150).toList(), 1: (1..150).toList()]
        // the first of the two to be heard keeps the plain id; the other is named after its link
        ids.findAll { it.contains('@') }.every { comms.node(it).link.index() == (it.split('@')[1] as int) - 1 }

        cleanup:
        fleet?.close()
        comms?.close()
    }
}
