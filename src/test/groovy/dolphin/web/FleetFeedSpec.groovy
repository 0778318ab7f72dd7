package dolphin.web

import com.MAVLink.enums.MAV_VTOL_STATE
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.core.TaskTree
import dolphin.mavlink.LinkHealth
import dolphin.mavlink.RadioStatus
import java.time.Duration
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import groovy.json.JsonSlurper
import dolphin.mission.model.MissionType
import dolphin.mission.transfer.TransferPath
import dolphin.mission.transfer.TransferStatus
import spock.lang.Specification

/** Frames from samples, and what a viewer that has frame N is sent: no sockets, no threads, no clock. */
class FleetFeedSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    TaskBoard board = new TaskBoard(0)
    List<VehicleSample> samples = []
    int drawn
    List<LinkView> links = []
    FleetFeed feed = new FleetFeed({ samples } as java.util.function.Supplier, { links } as java.util.function.Supplier, board)

    static VehicleState state(Position at, boolean armed = true, int item = 2) {
        def hb = new msg_heartbeat(base_mode: (short) (armed ? 128 : 0), custom_mode: 3)
        VehicleState.initial(VehicleFamily.COPTER).withHeartbeat(hb, 0).withPosition(at, at.hae() - 820, 90.0, 0)
                .withHome(HOME).withMissionCurrent(item, 5, MISSION_STATE.MISSION_STATE_ACTIVE)
    }

    VehicleSample sample(String id, Position at, Object mission = null) {
        new VehicleSample(VehicleView.of(id, 'UAV', true, id == '1', state(at), board.vehicleTasks().getOrDefault(id, '')), mission,
                { drawn++; '{"type":"FeatureCollection","name":"m","features":[]}' })
    }

    static Map parse(String json) {
        new JsonSlurper().parseText(json) as Map
    }

    def "a vehicle's view: position, heading, mode, item, picked"() {
        given:
        samples = [sample('1', HOME.displace(10, 0, -50))]

        when:
        def frame = feed.sample(1.0)
        def v = parse(frame.vehicles()['1'].json())

        then:
        v.id == '1' && v.type == 'UAV' && v.family == 'ArduCopter'
        Math.abs((v.position[0] as double) - HOME.displace(10, 0, -50).latitudeDegrees()) < 1e-7
        v.position[2] == 870.0
        v.relativeAlt == 50.0
        v.heading == 90.0
        v.mode == 'AUTO' && v.armed && v.picked
        v.item == 2 && v.total == 5
        v.home == [40.444233, -7.375234, 820.0]
    }

    def "a QuadPlane's view says how it flies (#text), from EXTENDED_SYS_STATE's VTOL state; a copter's says nothing"() {
        given:
        def s = VehicleState.initial(VehicleFamily.PLANE).withHeartbeat(new msg_heartbeat(custom_mode: 10), 0).withExtendedState(2, vtolState)

        when:
        def v = parse(VehicleView.of('1', 'UAV', true, false, s, '').json())

        then:
        v.vtol == text
        v.family == family

        where:
        vtolState                                     || text       | family
        MAV_VTOL_STATE.MAV_VTOL_STATE_MC              || 'hovering' | 'ArduPlane VTOL'
        MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_FW || 'to plane' | 'ArduPlane VTOL'
        MAV_VTOL_STATE.MAV_VTOL_STATE_FW              || 'plane'    | 'ArduPlane VTOL'
        MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_MC || 'to hover' | 'ArduPlane VTOL'
        MAV_VTOL_STATE.MAV_VTOL_STATE_UNDEFINED       || null       | 'ArduPlane'
    }

    def "a vehicle's payloads and latest readings, a stale one marked, a NaN one as text"() {
        given:
        samples = [new VehicleSample(VehicleView.of('1', 'UAV', true, -1, false, state(HOME), '', ['Camera', 'SMOKE'],
                [new VehicleView.Shown('SMOKE', 42.5d, '', 1, true), new VehicleView.Shown('TEMP', Double.NaN, 'degC', 191, false)],
                null, null), null, { null })]

        when:
        def v = parse(feed.sample(1.0).vehicles()['1'].json())

        then:
        v.payloads == ['Camera', 'SMOKE']
        v.readings == [[name: 'SMOKE', value: 42.5, unit: '', component: 1, fresh: true],
                       [name: 'TEMP', value: 'NaN', unit: 'degC', component: 191, fresh: false]]
    }

    def "a transfer in progress is sent with its list, path, amount, resends and text; none is null"() {
        given:
        def status = new TransferStatus(MissionType.FENCE, true, TransferPath.FTP, 620, 1530, 2)
        samples = [new VehicleSample(VehicleView.of('1', 'UAV', true, -1, false, state(HOME), '', [], [], status, null), null, { null }),
                   sample('2', HOME)]

        when:
        def frame = feed.sample(1.0)

        then:
        parse(frame.vehicles()['1'].json()).transfer == [upload: true, list: 'fence', path: 'ftp', done: 620, total: 1530,
                                                          unit: 'bytes', resends: 2, text: 'uploading the fence over FTP: 620 of 1,530 bytes, 2 resent']
        parse(frame.vehicles()['2'].json()).transfer == null
    }

    static final String SERIAL = 'serial:/dev/ttyUSB0:57600'
    static final RadioStatus RADIO = new RadioStatus(124, 118, 40, 45, 6, 9, 97, 0)

    VehicleSample onLink(String id, String link) {
        new VehicleSample(VehicleView.of(id, 'UAV', true, -1, false, state(HOME), '', [], [], null, link), null, { null })
    }

    static LinkView view(double in, double out, RadioStatus radio = null, double radioAge = 0) {
        LinkView.of(new LinkHealth(SERIAL, in, out, 9000, 4000, 3, 1, 2, radio, radio ? Duration.ofMillis(Math.round(radioAge * 1000)) : null))
    }

    static Map linkJson(FleetFeed.FeedFrame frame) {
        parse(frame.links()[SERIAL].json())
    }

    def "each link is sent apart from its vehicles, which name it: rates to 100 B/s, losses, the radio's report"() {
        given:
        samples = [onLink('1', SERIAL), sample('2', HOME)]
        links = [view(1234, 3456, RADIO, 0.5)]

        when:
        def all = parse(FleetFeed.update(feed.sample(1.0), 0, new EventLog(1).since(0), ''))

        then:
        all.links == [(SERIAL): [name: SERIAL, in: 1200, out: 3500, lost: 3, badCrcs: 1,
                radio: [rssi: 124, remrssi: 118, noise: 40, remnoise: 45, rssiDbm: -62, remrssiDbm: -65, noiseDbm: -106,
                        remnoiseDbm: -103, rxerrors: 6, fixed: 9, txbuf: 97, silence: null]]]
        all.vehicles.find { it.id == '1' }.link == SERIAL
        all.vehicles.find { it.id == '2' }.link == null

        when: 'a radio whose report is old news, one that does not know its signal, a link without a radio'
        links = [view(0, 0, RADIO, 12.5)]
        def stale = linkJson(feed.sample(2.0))
        links = [view(0, 0, new RadioStatus(255, 118, 255, 45, 0, 0, 50, 0), 1)]
        def unknown = linkJson(feed.sample(3.0))
        links = [view(250, 40)]
        def plain = linkJson(feed.sample(4.0))

        then:
        stale.radio.silence == 12
        unknown.radio.rssiDbm == null && unknown.radio.noiseDbm == null && unknown.radio.remrssiDbm == -65
        plain.radio == null && plain.in == 300 && plain.out == 0
    }

    def "a link whose rates change is sent again, not its vehicles; rates that round the same and a current report's age send nothing"() {
        given:
        samples = [onLink('1', SERIAL), onLink('2', SERIAL)]
        links = [view(1210, 3420, RADIO, 0.2)]
        def first = feed.sample(1.0)

        when:
        links = [view(1160, 3440, RADIO, 3.9)]
        def second = parse(FleetFeed.update(feed.sample(1.25), first.number(), new EventLog(1).since(0), ''))

        then:
        second.links.isEmpty() && second.vehicles.isEmpty()

        when:
        links = [view(1290, 3440, RADIO, 4.1)]
        def third = parse(FleetFeed.update(feed.sample(1.5), first.number(), new EventLog(1).since(0), ''))

        then:
        third.links.values()*.in == [1300]
        third.vehicles.isEmpty()
    }

    def "a silent vehicle is sent with the seconds of its silence, a heard one with null; each second more is a change"() {
        given:
        def silent = { int seconds -> new VehicleSample(VehicleView.of('1', 'UAV', true, seconds, false, state(HOME), '', [], [], null, null), null, { null }) }
        samples = [silent(7), sample('2', HOME)]

        when:
        def frame = feed.sample(1.0)

        then:
        parse(frame.vehicles()['1'].json()).silence == 7
        parse(frame.vehicles()['1'].json()).connected
        parse(frame.vehicles()['2'].json()).silence == null

        when:
        samples = [silent(8), sample('2', HOME)]
        def next = feed.sample(2.0)

        then:
        parse(FleetFeed.update(next, frame.number(), new EventLog(1).since(0), '')).vehicles*.silence == [8]
    }

    def "a viewer that has frame N is sent only the vehicles that changed after N, however many frames it missed"() {
        given:
        samples = [sample('1', HOME), sample('2', HOME)]
        def first = feed.sample(1.0)

        when: 'vehicle 2 moves in frame 2, nothing in frame 3'
        samples = [sample('1', HOME), sample('2', HOME.displace(5, 0, 0))]
        feed.sample(1.25)
        def third = feed.sample(1.5)

        then:
        parse(FleetFeed.update(third, first.number(), new EventLog(1).since(0), '')).vehicles*.id == ['2']
        parse(FleetFeed.update(third, third.number() - 1, new EventLog(1).since(0), '')).vehicles.isEmpty()
        parse(FleetFeed.update(third, 0, new EventLog(1).since(0), '')).vehicles*.id as Set == ['1', '2'] as Set
        third.number() == first.number() + 2
    }

    def "a mission is drawn once per executor, and sent when new"() {
        given:
        def executor = new Object()
        samples = [sample('1', HOME, executor)]
        def first = feed.sample(1)

        when:
        def second = feed.sample(2)

        then:
        drawn == 1
        parse(FleetFeed.update(first, 0, new EventLog(1).since(0), '')).missions.keySet() == ['1'] as Set
        parse(FleetFeed.update(second, first.number(), new EventLog(1).since(0), '')).missions.isEmpty()

        when: 'a new mission on the vehicle'
        samples = [sample('1', HOME, new Object())]
        def third = feed.sample(3)

        then:
        drawn == 2
        parse(FleetFeed.update(third, second.number(), new EventLog(1).since(0), '')).missions.keySet() == ['1'] as Set
    }

    def "the trees are sent when they changed, with the log entries and how many were lost"() {
        given:
        def first = feed.sample(1)
        board.executeStarted(new TaskTree(7, 'idle', 'idle 1.0 s', [], []))
        def second = feed.sample(2)
        def log = new EventLog(2)
        (1..3).each { log.add(it, 'message', null, "m${it}") }

        expect:
        !parse(FleetFeed.update(second, second.number(), log.since(3), '')).containsKey('executes')
        def update = parse(FleetFeed.update(second, first.number(), log.since(0), ',"extra":1'))
        update.executes*.label == ['idle 1.0 s']
        update.log*.text == ['m2', 'm3']
        update.logLost == 1
        update.extra == 1
    }

    def "tracks grow from the positions sampled"() {
        given:
        (0..<10).each { i ->
            samples = [sample('1', HOME.displace(i * 3, 0, 0))]
            feed.sample(i)
        }

        expect:
        (parse(feed.tracksJson())['1'] as List).size() == 10
    }
}
