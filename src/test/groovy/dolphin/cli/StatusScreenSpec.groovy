package dolphin.cli

import dolphin.mavlink.LinkHealth
import dolphin.mavlink.RadioStatus
import java.time.Duration
import spock.lang.Specification

/** The vehicles' status: plain lines on change for logs, a table redrawn in place on a terminal. */
class StatusScreenSpec extends Specification {

    static final LinkHealth QUIET_UDP = link(0, 0)

    static VehicleStatus status(Map m = [:]) {
        new VehicleStatus(m.id ?: '1', m.containsKey('connected') ? m.connected : true, m.containsKey('silence') ? m.silence : -1,
                m.mode ?: 'GUIDED', m.armed ?: false, m.battery ?: 100, m.alt ?: 0.0d, m.item ?: 0, m.total ?: 0, m.task ?: '', m.transfer ?: '',
                m.link ?: QUIET_UDP)
    }

    /** A link's health: its rates in and out, and a radio's report of {@code radioAge} seconds ago, or none. */
    static LinkHealth link(double in, double out, RadioStatus radio = null, double radioAge = 0) {
        new LinkHealth(radio ? 'serial:/dev/ttyUSB0:57600' : 'udpin:0.0.0.0:14559', in, out, 0, 0, 0, 0, 0, radio,
                radio ? Duration.ofMillis(Math.round(radioAge * 1000)) : null)
    }

    /** A SiK radio's report: 124 and 118 are -62 and -65 dBm on its scale. */
    static RadioStatus radio(int rssi = 124, int remrssi = 118, int txbuf = 97) {
        new RadioStatus(rssi, remrssi, 40, 45, 0, 0, txbuf, 0)
    }

    def "the link column shows the link's kB/s in and out; a radio's report ends the row, and the sentence with the rates"() {
        given:
        def onRadio = status(task: 'survey running', link: link(1200, 3400, radio(), 0.8))

        expect:
        onRadio.row() == '1        GUIDED           disarmed   100 %     0.0 m -         1.2/3.4 kB/s survey running, radio -62/-65 dBm txbuf 97%'
        onRadio.sentence() == 'vehicle 1: GUIDED, disarmed, battery 100 %, altitude 0.0 m, task survey running, radio -62/-65 dBm txbuf 97% 1.2/3.4 kB/s'

        and: 'no radio: the rates in their column, nothing more; the sentence as it always was'
        status(link: link(1200, 3400)).row() == '1        GUIDED           disarmed   100 %     0.0 m -         1.2/3.4 kB/s '
        status(link: link(1200, 3400)).sentence() == 'vehicle 1: GUIDED, disarmed, battery 100 %, altitude 0.0 m'

        and: 'whole kilobytes from ten on, so the column stays narrow'
        status(link: link(123_456, 9_960)).rateText() == '123/10 kB/s'
        status(link: link(9_940, 49)).rateText() == '9.9/0.0 kB/s'

        and: 'a signal the radio does not know, and a radio whose last report is old news'
        status(link: link(0, 0, radio(255, 118, 50))).radioText() == 'radio ?/-65 dBm txbuf 50%'
        status(link: link(0, 0, radio(), 12.4)).radioText() == 'radio silent 12 s'
        status(transfer: 'uploading: 4 of 9 items', link: link(0, 0, radio(), 12.4)).row()
                .endsWith(' 0.0/0.0 kB/s uploading: 4 of 9 items, radio silent 12 s')
    }

    def "plain: a radio's changing report and the link's rates make no line of their own"() {
        given:
        def out = new StringWriter()
        def screen = new PlainScreen(new PrintWriter(out), { '[t] ' })

        when:
        screen.refresh([status(link: link(1200, 3400, radio(), 0.2))])
        screen.refresh([status(link: link(900, 3100, radio(110, 100, 40), 0.4))])
        screen.refresh([status(link: link(0, 0, radio(110, 100, 40), 9))])
        screen.refresh([status(link: link(0, 0))])

        then:
        out.toString().readLines() == ['[t] vehicle 1: GUIDED, disarmed, battery 100 %, altitude 0.0 m, radio -62/-65 dBm txbuf 97% 1.2/3.4 kB/s']
    }

    def "a transfer in progress shows after the task, in the sentence and the table's row, and makes no log line of its own"() {
        given:
        def uploading = status(task: 'survey running', transfer: 'uploading: 45 of 100 items, 3 resent')
        def out = new StringWriter()
        def screen = new PlainScreen(new PrintWriter(out), { '' })

        when:
        screen.refresh([status(task: 'survey running')])
        screen.refresh([uploading])

        then:
        uploading.sentence().endsWith('task survey running, uploading: 45 of 100 items, 3 resent')
        uploading.row().endsWith('survey running, uploading: 45 of 100 items, 3 resent')
        status(transfer: 'uploading over FTP: 620 of 3,810 bytes').row().endsWith(' uploading over FTP: 620 of 3,810 bytes')
        out.toString().readLines().size() == 1
    }

    def "a status reads as a sentence, with the mission item and the task when there are any"() {
        expect:
        status().sentence() == 'vehicle 1: GUIDED, disarmed, battery 100 %, altitude 0.0 m'
        status(mode: 'AUTO', armed: true, battery: 82, alt: 45.25d, item: 3, total: 44, task: 'survey running').sentence() ==
                'vehicle 1: AUTO, armed, battery 82 %, altitude 45.3 m, item 3 of 44, task survey running'
        status(connected: false, battery: -1).sentence() == 'vehicle 1: LOST, last seen GUIDED, disarmed, battery ?, altitude 0.0 m'
    }

    def "plain: a line when mode, arming, connection or task change; not for battery, height or item alone"() {
        given:
        def out = new StringWriter()
        def screen = new PlainScreen(new PrintWriter(out), { '[t] ' })

        when:
        screen.refresh([status(), status(id: '2')])
        screen.refresh([status(battery: 90, alt: 12d, item: 2, total: 5), status(id: '2')])
        screen.refresh([status(armed: true), status(id: '2', task: 'hop running')])
        screen.line('a message')
        screen.refresh([status(armed: true), status(id: '2', task: 'hop running', connected: false)])

        then:
        out.toString().readLines() == [
                '[t] vehicle 1: GUIDED, disarmed, battery 100 %, altitude 0.0 m',
                '[t] vehicle 2: GUIDED, disarmed, battery 100 %, altitude 0.0 m',
                '[t] vehicle 1: GUIDED, armed, battery 100 %, altitude 0.0 m',
                '[t] vehicle 2: GUIDED, disarmed, battery 100 %, altitude 0.0 m, task hop running',
                '[t] a message',
                '[t] vehicle 2: LOST, last seen GUIDED, disarmed, battery 100 %, altitude 0.0 m, task hop running']
    }

    def "live: lines scroll above a table that is erased and redrawn in place"() {
        given:
        def out = new StringWriter()
        def screen = new LiveScreen(new PrintWriter(out), { '[t] ' }, 20)

        when:
        screen.refresh([status(), status(id: '2', mode: 'AUTO', armed: true, item: 1, total: 4, task: 'hop running')])
        screen.line('a message')

        then:
        def table = [VehicleStatus.HEADER,
                     '1        GUIDED           disarmed   100 %     0.0 m -         0.0/0.0 kB/s ',
                     '2        AUTO             armed      100 %     0.0 m 1/4       0.0/0.0 kB/s hop running']
        out.toString() == (table + ["\033[3F\033[J[t] a message"] + table).join('\n') + '\n'
    }

    def "live: a large fleet shows its first rows and sums up the others by mode"() {
        given:
        def screen = new LiveScreen(new PrintWriter(new StringWriter()), { '' }, 3)
        def fleet = (1..10).collect { status(id: "$it", mode: it % 2 ? 'AUTO' : 'RTL', connected: it != 10) }

        when:
        def rows = screen.table(fleet)

        then:
        rows.size() == 5
        rows[1].startsWith('1 ')
        rows[3].startsWith('3 ')
        rows[4] == '... and 7 more: 3 AUTO, 1 LOST, 3 RTL'
    }

    def "plain: a silence makes a line as it starts and as it ends, none as it lengthens; its sentence says how long"() {
        given:
        def out = new StringWriter()
        def screen = new PlainScreen(new PrintWriter(out), { '[t] ' })

        when:
        [-1, 3, 4, 9, -1].each { screen.refresh([status(mode: 'AUTO', armed: true, silence: it)]) }

        then:
        out.toString().readLines() == [
                '[t] vehicle 1: AUTO, armed, battery 100 %, altitude 0.0 m',
                '[t] vehicle 1: no contact 3 s, last seen AUTO, armed, battery 100 %, altitude 0.0 m',
                '[t] vehicle 1: AUTO, armed, battery 100 %, altitude 0.0 m']
        status(connected: false, silence: 25).sentence().startsWith('vehicle 1: LOST, last seen GUIDED')
    }

    def "live: a large fleet counts its silent vehicles apart from their modes and from the lost ones"() {
        given:
        def screen = new LiveScreen(new PrintWriter(new StringWriter()), { '' }, 1)
        def fleet = [status(id: '1'), status(id: '2', mode: 'AUTO', silence: 4), status(id: '3', mode: 'AUTO', silence: 12),
                     status(id: '4', mode: 'AUTO'), status(id: '5', connected: false, silence: 30)]

        expect:
        screen.table(fleet).last() == '... and 4 more: 1 AUTO, 1 LOST, 2 no contact'
    }

    def "live: a log line with its own timestamp goes above the table, which is redrawn below it"() {
        given:
        def out = new StringWriter()
        def screen = new LiveScreen(new PrintWriter(out), { '[t] ' }, 20)
        screen.refresh([status()])

        when:
        screen.above('09:00:00 [INFO] vehicle 1: Reached command #1')

        then:
        out.toString().readLines().takeRight(3) == ["\033[2F\033[J09:00:00 [INFO] vehicle 1: Reached command #1".toString(),
                                                    VehicleStatus.HEADER, status().row()]
    }

    def "standard error's bytes become whole lines for the screen; a last unfinished line comes on close"() {
        given:
        def lines = []
        def stream = new TerminalErr.Lines({ lines << it })

        when:
        stream.write('first line\r\nsecond '.bytes)
        stream.write('line\nno newline'.bytes)

        then:
        lines == ['first line', 'second line']

        when:
        stream.close()

        then:
        lines == ['first line', 'second line', 'no newline']
    }
}
