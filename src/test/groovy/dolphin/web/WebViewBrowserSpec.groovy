package dolphin.web

import com.MAVLink.common.msg_radio_status
import com.MAVLink.enums.PLANE_MODE
import dolphin.core.SystemClock
import dolphin.dsl.Engine
import dolphin.dsl.ScriptResult
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.codec.FrameWriter
import dolphin.platform.MAVLinkPlatform
import dolphin.sim.PlumeField
import dolphin.sim.SimEquipment
import dolphin.sim.SimFleet
import dolphin.sim.SimSensor
import dolphin.sim.SysidSet
import dolphin.sim.VehicleKind
import java.nio.file.Files
import java.nio.file.Path
import java.time.Duration
import org.openqa.selenium.By
import org.openqa.selenium.OutputType
import org.openqa.selenium.WebDriver
import org.openqa.selenium.chrome.ChromeDriver
import org.openqa.selenium.support.ui.WebDriverWait
import spock.lang.Requires
import spock.lang.Specification
import spock.lang.Timeout

/**
 * The page in a real browser: Debian's chromium, driven by Selenium, watches
 * the report's two-vehicle scenario (dsl-examples/two-drones-survey.dolphin) on the simulated fleet.
 * The browser is on the page before the script starts, so every phase is seen as it happens. It
 * saves target/web-view-survey.png (the surveys flying) and target/web-view.png (the end); a mapping
 * mission (dsl-examples/mapping.dolphin) shows its survey's drawing in target/web-view-mapping.png.
 */
@Requires({ Chromium.available() })
@Timeout(180)
class WebViewBrowserSpec extends Specification {

    static final double SPEEDUP = 20

    SystemClock clock = new SystemClock(SPEEDUP)
    MAVLinkCommunications comms
    SimFleet fleet
    Engine engine
    WebView view
    ChromeDriver browser

    def setup() {
        comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
        comms.start()
        // vehicle 1 reads a smoke plume around home, vehicle 2 carries a camera
        def equipment = new SimEquipment([new SimSensor('SMOKE', new PlumeField(SimFleet.Config.DEFAULT_HOME, 2000, 100, 0),
                SysidSet.of([1]))], SysidSet.of([2]))
        fleet = new SimFleet(SimFleet.Config.of(2, VehicleKind.COPTER,
                new InetSocketAddress('127.0.0.1', comms.links()[0].localPort())).withEquipment(equipment), clock)
        fleet.start()
        engine = new Engine(new MAVLinkPlatform(comms), clock)
        view = WebView.start(new WebView.Settings(WebAddress.parse('0'), null), comms, engine, SystemClock.REAL)
        browser = Chromium.start()
    }

    def cleanup() {
        browser?.quit()
        engine?.close()
        view?.close()
        fleet?.close()
        comms?.close()
    }

    def "the page shows both vehicles moving, the surveys running, stopped at the battery cut, the returns done, and the cut in the log"() {
        given: 'the page open and live before the script starts'
        browser.get(view.address())
        waitUntil(10) { $('#connection[data-state="live"]') }

        when:
        def run = engine.run(Path.of('dsl-examples/two-drones-survey.dolphin'))

        then: 'both vehicles appear in the table and on the map'
        waitUntil(30) { positions().keySet() == ['1', '2'] as Set }
        waitUntil(10) { browser.executeScript('return document.querySelectorAll("path.dolphin-vehicle").length') == 2 }

        and: 'vehicle 1 shows its smoke reading in the table, vehicle 2 none'
        waitUntil(30) { $('#vehicles tr[data-vehicle="1"] [data-reading="SMOKE"][data-fresh="true"]') }
        !$('#vehicles tr[data-vehicle="2"] [data-reading]')

        and: 'the surveys run, each on its vehicle'
        waitUntil(30) { node('Survey Area 1', 'running') && node('Survey Area 2', 'running') }
        node('Survey Area 1', 'running').contains('on 1')

        and: 'both vehicles move'
        def first = positions()
        waitUntil(30) {
            def now = positions()
            ['1', '2'].every { id -> Math.abs(now[id][0] - first[id][0]) + Math.abs(now[id][1] - first[id][1]) > 2e-5 }
        }

        screenshot('web-view-survey.png')

        and: 'the surveys are stopped at the battery cut, then the return missions are done'
        waitUntil(60) { node('Survey Area 1', 'stopped') && node('Survey Area 2', 'stopped') }
        waitUntil(60) { node('Return to base 1', 'done') && node('Return to base 2', 'done') }

        and: 'the log shows the cut'
        waitUntil(10) { logText().contains('vehicle { 1 } cut short at battery') && logText().contains('vehicle { 2 } cut short at battery') }
        logText().contains('task Survey Area 1 stopped')

        and: 'the script completes'
        run.await(Duration.ofSeconds(60)).outcome() == ScriptResult.Outcome.COMPLETED
        waitUntil(10) { logText().contains('two-drones-survey.dolphin: completed') }

        cleanup:
        screenshot('web-view.png')
    }

    def "a mapping mission draws its survey polygon, its corridor's path and the photos' footprints"() {
        given:
        browser.get(view.address())
        waitUntil(10) { $('#connection[data-state="live"]') }

        when:
        def run = engine.run(Path.of('dsl-examples/mapping.dolphin'))

        then: 'the survey polygon and the corridor path, each an element of its own, and the footprints'
        waitUntil(60) { browser.executeScript('return document.querySelectorAll("path.dolphin-survey").length') == 2 }
        browser.executeScript('return document.querySelectorAll("path.dolphin-footprints").length') == 2
        screenshot('web-view-mapping.png')

        and:
        run.await(Duration.ofSeconds(90)).outcome() == ScriptResult.Outcome.COMPLETED
    }

    def "a vehicle that falls silent: its row and label say no contact, the log says when contact was lost and when it came back"() {
        given: 'vehicle 2 given ten minutes before it is lost, so its silence shows as a silence'
        browser.get(view.address())
        waitUntil(10) { $('#connection[data-state="live"]') }
        waitUntil(30) { positions().keySet() == ['1', '2'] as Set }
        comms.node('2').connectionTimeout = 600

        when:
        fleet.vehicle(2).silent = true

        then:
        waitUntil(10) { $('#vehicles tr[data-vehicle="2"][data-silent="true"]') }
        modeCell('2') ==~ /no contact \d+ s/
        $('#vehicles tr[data-vehicle="1"][data-silent="false"]')
        waitUntil(10) { labels().contains('2 no contact') }
        !labels().contains('1 no contact')
        waitUntil(10) { logText().contains('2 no contact for 3 s') }
        screenshot('web-view-silent.png')

        when:
        fleet.vehicle(2).silent = false

        then:
        waitUntil(10) { $('#vehicles tr[data-vehicle="2"][data-silent="false"]') }
        waitUntil(10) { logText() =~ /2 contact again after \d+ s/ }
        labels().contains('2')
    }

    def "the link column shows the link's rates, and a telemetry radio's report once one comes; the radio is no vehicle"() {
        given:
        browser.get(view.address())
        waitUntil(10) { $('#connection[data-state="live"]') }
        waitUntil(30) { positions().keySet() == ['1', '2'] as Set }
        def radio = new FrameWriter(51, 68)
        def socket = new DatagramSocket()
        def ground = new InetSocketAddress('127.0.0.1', comms.links()[0].localPort())

        expect: 'rates in kB/s, and no radio on a plain UDP link'
        waitUntil(10) { linkCell('1') ==~ /\d+\.\d\/\d+\.\d kB\/s/ && linkCell('1') != '0.0/0.0 kB/s' }
        !$('#vehicles .dolphin-radio')

        and: 'a SiK radio on the link reports, as it does on each of our heartbeats (here on each look)'
        waitUntil(10) {
            byte[] f = radio.write(new msg_radio_status(rssi: 124, remrssi: 118, noise: 40, remnoise: 45, txbuf: 97))
            socket.send(new DatagramPacket(f, f.length, ground))
            $('#vehicles tr[data-vehicle="2"] .dolphin-radio[data-radio="current"]')
        }
        linkCell('1') ==~ /\d+\.\d\/\d+\.\d kB\/s radio -62\/-65 dBm txbuf 97%/
        comms.nodes()*.id == ['1', '2']

        cleanup:
        socket?.close()
    }

    def "a QuadPlane's row says how it flies, from its VTOL state: plane in FLY_BY_WIRE_A, hovering on the ground in AUTO; a copter's says nothing of it"() {
        given: 'a QuadPlane, vehicle 3, beside the two copters'
        browser.get(view.address())
        waitUntil(10) { $('#connection[data-state="live"]') }
        def quadplane = new SimFleet(SimFleet.Config.of(1, VehicleKind.QUADPLANE,
                new InetSocketAddress('127.0.0.1', comms.links()[0].localPort())).withFirstSysid(3), clock)
        quadplane.start()

        expect:
        waitUntil(30) { modeCell('3') == 'FLY_BY_WIRE_A, plane' }
        modeCell('1') == 'STABILIZE'

        when:
        quadplane.vehicle(3).setMode(PLANE_MODE.PLANE_MODE_AUTO)

        then:
        waitUntil(10) { modeCell('3') == 'AUTO, hovering' }

        cleanup:
        quadplane?.close()
    }

    /** The link column of a vehicle's row in the table. */
    private String linkCell(String id) {
        (browser.executeScript('return document.querySelector(`#vehicles tr[data-vehicle="${arguments[0]}"] td.dolphin-link`).innerText', id) as String)
                .replaceAll(/\s+/, ' ').trim()
    }

    /** The mode column of a vehicle's row in the table. */
    /** The mode column of a vehicle's row, or null before the row is drawn (a wait asks again). */
    private String modeCell(String id) {
        browser.executeScript('return document.querySelector(`#vehicles tr[data-vehicle="${arguments[0]}"] td:nth-child(3)`)?.innerText', id)
    }

    /** The vehicles' labels on the map. */
    private List<String> labels() {
        browser.executeScript('return [...document.querySelectorAll(".vehicle-label")].map(e => e.innerText)') as List<String>
    }

    /** Saves what the browser shows in target/, for a person to look at. */
    private void screenshot(String name) {
        if (browser != null) {
            Path shot = Path.of('target', name)
            Files.createDirectories(shot.parent)
            Files.write(shot, browser.getScreenshotAs(OutputType.BYTES))
        }
    }

    // The page redraws its table and tree every frame: each read is one script, never a stale element.

    private Map<String, List<Double>> positions() {
        List rows = browser.executeScript('''return [...document.querySelectorAll('#vehicles tbody tr')]
                .filter(r => r.dataset.lat !== 'null').map(r => [r.dataset.vehicle, +r.dataset.lat, +r.dataset.lon])''') as List
        rows.collectEntries { [it[0], [it[1] as double, it[2] as double]] }
    }

    /** The text of the task tree's node with this label in this state, or null. */
    private String node(String label, String state) {
        browser.executeScript('return [...document.querySelectorAll("li.node")].filter(n => n.dataset.label === arguments[0] '
                + '&& n.dataset.state === arguments[1]).map(n => n.querySelector(".row").innerText)[0] || null', label, state)
    }

    private String logText() {
        browser.executeScript('return document.getElementById("log").innerText')
    }

    private def $(String css) {
        browser.executeScript('return document.querySelector(arguments[0]) !== null', css) ?: null
    }

    /** Polls the page every 100 ms until the condition is truthy, failing after {@code seconds}. */
    private void waitUntil(int seconds, Closure<?> condition) {
        new WebDriverWait(browser, Duration.ofSeconds(seconds), Duration.ofMillis(100)).until { WebDriver d -> condition() ?: null }
    }
}
