package dolphin.web

import dolphin.core.SystemClock
import dolphin.dsl.Engine
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.platform.MAVLinkPlatform
import dolphin.sim.SimFleet
import dolphin.sim.VehicleKind
import groovy.json.JsonSlurper
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.time.Duration
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import spock.lang.Specification
import spock.lang.Timeout
import spock.util.concurrent.PollingConditions

/**
 * The web view over real HTTP on 127.0.0.1, with one simulated vehicle: the JSON state, the event
 * stream, viewers that go away or never read, the token beyond loopback, and the addresses it cannot
 * listen on. Waits are conditions with deadlines.
 */
@Timeout(60)
class WebViewSpec extends Specification {

    SystemClock clock = new SystemClock(10)
    MAVLinkCommunications comms
    SimFleet fleet
    Engine engine
    WebView view
    HttpClient http = HttpClient.newHttpClient()
    PollingConditions within = new PollingConditions(timeout: 15, delay: 0.05)
    List<Closeable> streams = []

    def setup() {
        comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
        comms.start()
        fleet = new SimFleet(SimFleet.Config.of(1, VehicleKind.COPTER,
                new InetSocketAddress('127.0.0.1', comms.links()[0].localPort())), clock)
        fleet.start()
        engine = new Engine(new MAVLinkPlatform(comms), clock)
    }

    def cleanup() {
        streams*.close()
        engine?.close()
        view?.close()
        fleet?.close()
        comms?.close()
    }

    WebView start(String address = '0') {
        view = WebView.start(new WebView.Settings(WebAddress.parse(address), 'https://tiles.example/{z}/{x}/{y}.png'), comms, engine,
                SystemClock.REAL)
        view
    }

    URI uri(String path) {
        URI.create(view.address().replaceFirst(/\/(\?.*)?$/, '') + path)
    }

    HttpResponse<String> get(URI uri, Map<String, String> headers = [:], String method = 'GET') {
        def request = HttpRequest.newBuilder(uri).method(method, HttpRequest.BodyPublishers.noBody())
        headers.each { k, v -> request.header(k, v) }
        http.send(request.build(), HttpResponse.BodyHandlers.ofString())
    }

    /** The events of a stream as [event, json] pairs, read on their own thread. */
    LinkedBlockingQueue<List> stream(URI uri, Map<String, String> headers = [:]) {
        def events = new LinkedBlockingQueue<List>()
        def request = HttpRequest.newBuilder(uri)
        headers.each { k, v -> request.header(k, v) }
        def response = http.send(request.build(), HttpResponse.BodyHandlers.ofInputStream())
        assert response.statusCode() == 200
        def body = response.body()
        streams << body
        Thread.start('sse reader') {
            String event = null
            try {
                body.newReader('UTF-8').eachLine { line ->
                    if (line.startsWith('event: ')) event = line.substring(7)
                    else if (line.startsWith('data: ')) events << [event, new JsonSlurper().parseText(line.substring(6))]
                }
            } catch (IOException ignored) {
                // the test closed the stream
            }
        }
        events
    }

    static List next(LinkedBlockingQueue<List> events, String kind, Closure<Boolean> matching = { true }) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(15)
        while (System.nanoTime() < deadline) {
            def e = events.poll(100, TimeUnit.MILLISECONDS)
            if (e != null && e[0] == kind && matching(e[1])) {
                return e
            }
        }
        throw new AssertionError("no '${kind}' event as expected within 15 s")
    }

    def "/state has the vehicles, where they are and the settings; the page and Leaflet are served from the jar"() {
        given:
        start()

        expect:
        view.address() ==~ /http:\/\/127\.0\.0\.1:\d+\//
        within.eventually {
            def state = new JsonSlurper().parseText(get(uri('/state')).body())
            assert state.vehicles*.id == ['1']
            assert state.vehicles[0].position != null
            assert state.config.tiles == 'https://tiles.example/{z}/{x}/{y}.png'
            assert state.config.periodMillis == 250
        }
        get(uri('/')).body().contains('<div id="map">')
        get(uri('/app.js')).headers().firstValue('Content-Type').get().startsWith('text/javascript')
        get(uri('/leaflet/leaflet.js')).statusCode() == 200
        get(uri('/leaflet/images/marker-icon.png')).headers().firstValue('Content-Type').get() == 'image/png'
        get(uri('/leaflet/../leaflet.js')).statusCode() in [400, 404]
        get(uri('/nothing')).statusCode() == 404
    }

    def "a stream starts with a snapshot, then updates carry the script's messages and task events, then the end"() {
        given:
        start()
        def events = stream(uri('/events'))

        when:
        def snapshot = next(events, 'snapshot')[1]
        engine.run('message "hello from the script"\nexecute idle(0.5)', 'hello.dolphin').await()

        then:
        snapshot.containsKey('tracks') && snapshot.containsKey('config')
        def updates = []
        next(events, 'update') { updates << it; updates.collectMany { u -> u.log*.text }.contains('hello from the script') }
        next(events, 'update') { updates << it; updates.findAll { u -> u.executes }[-1]?.executes?.getAt(0)?.state == 'done' }
        updates.findAll { it.executes }[-1].executes[0].kind == 'idle'
        next(events, 'update') { it.run.outcome == 'completed' }

        when:
        view.close()

        then:
        next(events, 'end')
    }

    def "a vehicle that falls silent, with no script running: its row counts the seconds, the log says contact lost, then contact again"() {
        given:
        start()
        within.eventually { assert new JsonSlurper().parseText(get(uri('/state')).body()).vehicles[0]?.position != null }

        when:
        fleet.vehicle(1).silent = true

        then:
        within.eventually {
            def state = new JsonSlurper().parseText(get(uri('/state')).body())
            assert state.vehicles[0].silence >= 3 && state.vehicles[0].connected
            assert state.log.find { it.kind == 'contact_lost' }?.subMap('vehicle', 'text') == [vehicle: '1', text: 'no contact for 3 s']
        }

        when:
        fleet.vehicle(1).silent = false

        then:
        within.eventually {
            def state = new JsonSlurper().parseText(get(uri('/state')).body())
            assert state.vehicles[0].silence == null
            assert state.log.find { it.kind == 'contact_again' }?.text ==~ /contact again after \d+ s/
        }
    }

    def "a viewer that goes away mid-stream ends its thread; the other viewer and the run go on"() {
        given:
        start()
        def staying = stream(uri('/events'))
        def leaving = stream(uri('/events'))
        next(leaving, 'snapshot')
        next(staying, 'snapshot')
        within.eventually { assert view.viewers() == 2 }

        when:
        streams[1].close()

        then:
        within.eventually { assert view.viewers() == 1 }
        def seen = next(staying, 'update')[1].frame as long
        next(staying, 'update') { (it.frame as long) > seen }
        engine.run('message "still running"', 'after.dolphin').await().exitCode() == 0
    }

    def "a viewer that never reads does not hold up the others"() {
        given: 'a log of about a megabyte, so the snapshot alone fills a viewer\'s socket buffers'
        start()
        (1..1500).each { view.message("line ${it} " + 'x' * 600) }

        and: 'a viewer that asks for the stream and never reads it'
        def stalled = new Socket('127.0.0.1', uri('/').port)
        stalled.receiveBufferSize = 1024
        stalled.outputStream.write("GET /events HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n".bytes)
        stalled.outputStream.flush()
        streams << stalled
        def reading = stream(uri('/events'))

        expect: 'the reading viewer gets twenty frames in a row while the other one reads nothing'
        def first = next(reading, 'snapshot')[1].frame as long
        next(reading, 'update') { (it.frame as long) >= first + 20 }
        view.viewers() == 2
    }

    def "read-only, and on loopback only for pages that name this machine"() {
        given:
        start()

        expect:
        get(uri('/state'), [:], 'POST').statusCode() == 405
        rawGet('evil.example:80').startsWith('HTTP/1.1 403')
        rawGet("localhost:${uri('/').port}").startsWith('HTTP/1.1 200')
    }

    def "beyond loopback every request needs the printed token: a wrong or missing one gets a 401"() {
        given:
        start('0.0.0.0:0')
        def token = (view.address() =~ /\?token=([0-9a-f]{32})$/)[0][1]
        def base = "http://127.0.0.1:${URI.create(view.address()).port}"

        expect:
        get(URI.create("${base}/")).statusCode() == 401
        get(URI.create("${base}/")).body().contains('wrong or missing token')
        get(URI.create("${base}/state?token=${'0' * 32}")).statusCode() == 401
        get(URI.create("${base}/events")).statusCode() == 401

        when:
        def page = get(URI.create("${base}/?token=${token}"))
        def cookie = page.headers().firstValue('Set-Cookie').get()

        then: 'the page, and with its cookie the page\'s own requests'
        page.statusCode() == 200
        cookie.startsWith("dolphin-token=${token};") && cookie.contains('HttpOnly')
        get(URI.create("${base}/leaflet/leaflet.js"), [Cookie: "dolphin-token=${token}"]).statusCode() == 200
        next(stream(URI.create("${base}/events"), [Cookie: "dolphin-token=${token}"]), 'snapshot')
    }

    def "a port in use, an unknown host or an address not of this machine: the exception says which"() {
        given:
        def taken = new ServerSocket(0, 1, InetAddress.getByName('127.0.0.1'))

        when:
        start("127.0.0.1:${taken.localPort}")

        then:
        def inUse = thrown(WebViewException)
        inUse.message == "--web 127.0.0.1:${taken.localPort}: port ${taken.localPort} is in use on 127.0.0.1 (another program, or another dolphin run, listens there)"

        when:
        start('no-such-host.invalid:8080')

        then:
        def unknown = thrown(WebViewException)
        unknown.message == '--web no-such-host.invalid:8080: unknown host no-such-host.invalid'

        when:
        start('192.0.2.1:8080')

        then:
        def notOurs = thrown(WebViewException)
        notOurs.message.startsWith('--web 192.0.2.1:8080: cannot listen there')

        cleanup:
        taken.close()
    }

    String rawGet(String host) {
        new Socket('127.0.0.1', uri('/').port).withCloseable { s ->
            s.outputStream.write("GET /state HTTP/1.1\r\nHost: ${host}\r\nConnection: close\r\n\r\n".bytes)
            s.inputStream.newReader().readLine()
        }
    }
}
