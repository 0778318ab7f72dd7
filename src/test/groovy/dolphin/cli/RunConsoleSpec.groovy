package dolphin.cli

import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.ManualClock
import dolphin.dsl.Engine
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkConfig
import dolphin.mavlink.MAVLinkNode
import dolphin.mavlink.VehicleFamily
import dolphin.platform.MAVLinkPlatform
import java.time.Duration
import spock.lang.Specification

/**
 * What `dolphin run` shows of a vehicle that falls silent, on a manual clock: the communications'
 * contact events reach the console through the platform and the engine, with no script running, as
 * lines; the status shows the silence instead of the mode until the vehicle is heard again, or LOST
 * after its connection timeout. The contact is checked as the communications thread checks it.
 */
class RunConsoleSpec extends Specification {

    static final int HEARTBEAT = msg_heartbeat.MAVLINK_MSG_ID_HEARTBEAT

    ManualClock clock = new ManualClock()
    MAVLinkCommunications comms = new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock)
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', comms, null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)
    Engine engine = new Engine(new MAVLinkPlatform(comms), clock)
    StringWriter out = new StringWriter()

    def setup() {
        // AUTO and armed, its heartbeat at 0 s
        node.update { it.withHeartbeat(new msg_heartbeat(custom_mode: 3, base_mode: 128 as short), clock.nanoTime()) }
    }

    RunConsole console(Screen screen) {
        def console = new RunConsole(screen, { [node] }, clock)
        engine.addListener(console)
        console
    }

    /** Time passes with nothing heard; the contact is checked at the end, as the communications thread's 250 ms timer does. */
    void silence(int seconds) {
        clock.advance(Duration.ofSeconds(seconds))
        node.contact().check().ifPresent(comms.&publish)
    }

    void hear() {
        node.contact().heard(HEARTBEAT).ifPresent(comms.&publish)
    }

    def "plain: the contact events are lines with the time, and the status says the silence once as it starts and once as it ends"() {
        given:
        def console = console(new PlainScreen(new PrintWriter(out), { '[t] ' }))
        console.refresh()

        when:
        silence(3)
        console.refresh()
        silence(4)
        console.refresh()
        hear()
        console.refresh()

        then:
        out.toString().readLines() == [
                '[t] vehicle 1: AUTO, armed, battery ?, altitude 0.0 m',
                '[t] vehicle 1: no contact for 3 s',
                '[t] vehicle 1: no contact 3 s, last seen AUTO, armed, battery ?, altitude 0.0 m',
                '[t] vehicle 1: contact again after 7 s',
                '[t] vehicle 1: AUTO, armed, battery ?, altitude 0.0 m']
    }

    def "live: a silent vehicle's row says for how long instead of its mode, and LOST once its connection timeout has passed"() {
        given:
        def screen = new LiveScreen(new PrintWriter(out), { '[t] ' }, 20)
        def console = console(screen)
        node.connectionTimeout = 10

        when:
        silence(7)
        console.refresh()

        then:
        out.toString().contains('[t] vehicle 1: no contact for 7 s\n')
        out.toString().readLines().last() == '1        no contact 7 s   armed          ?     0.0 m -         0.0/0.0 kB/s '

        when:
        silence(4)
        console.refresh()

        then:
        out.toString().readLines().last().startsWith('1        LOST             armed')
        screen.table([VehicleStatus.of(node, ''), StatusScreenSpec.status(id: '2', silence: 5)])[2].startsWith('2        no contact 5 s ')
    }
}
