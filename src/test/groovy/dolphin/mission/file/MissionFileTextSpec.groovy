package dolphin.mission.file

import java.nio.charset.StandardCharsets
import java.nio.file.Files
import java.nio.file.Path
import spock.lang.Specification
import spock.lang.TempDir

import static MissionFileFixtures.*

/** Reading mission files as users have them: a byte-order mark, another encoding, a file cut short; each error one line naming the file. */
class MissionFileTextSpec extends Specification {

    static final byte[] BOM = [0xEF, 0xBB, 0xBF] as byte[]

    @TempDir
    Path dir

    static byte[] withBom(String text) {
        byte[] utf8 = text.getBytes(StandardCharsets.UTF_8)
        byte[] bytes = new byte[BOM.length + utf8.length]
        System.arraycopy(BOM, 0, bytes, 0, BOM.length)
        System.arraycopy(utf8, 0, bytes, BOM.length, utf8.length)
        bytes
    }

    Path file(String name, byte[] bytes) {
        Path f = dir.resolve(name)
        Files.write(f, bytes)
        f
    }

    def "a UTF-8 byte-order mark (Windows editors write one) is no part of the text: #format reads the same items"() {
        given:
        def items = mission()
        String text = format.write('m', items)

        expect:
        format == MissionFormat.PLAN ? PlanFile.read(file('m.plan', withBom(text))) == PlanFile.read(text)
                : WaypointsFile.read(file('m.waypoints', withBom(text))) == WaypointsFile.read(text)
        format.read('\uFEFF' + text) == format.read(text)

        where:
        format << [MissionFormat.PLAN, MissionFormat.WAYPOINTS]
    }

    def "a file in another encoding is refused in one line naming the file and the first byte that is not UTF-8"() {
        given: 'Latin-1 text: a comment with an e acute (0xE9) after the header'
        byte[] bytes = "QGC WPL 110\n# \u00e9t\u00e9 survey\n".getBytes(StandardCharsets.ISO_8859_1)
        Path f = file('latin1.waypoints', bytes)
        int offset = "QGC WPL 110\n# ".length()

        when:
        WaypointsFile.read(f)

        then:
        def e = thrown(IllegalArgumentException)
        e.message == "${f}: not UTF-8 text: byte 0xE9 at offset ${offset}; save the file as UTF-8".toString()
        !e.message.contains('\n')
    }

    def "a plan cut short is refused in one line naming the file and the line where the JSON stopped"() {
        given:
        String text = PlanFile.write(mission())
        Path f = file('cut.plan', text.substring(0, text.length().intdiv(2)).getBytes(StandardCharsets.UTF_8))

        when:
        PlanFile.read(f)

        then:
        def e = thrown(IllegalArgumentException)
        e.message.startsWith("${f}: not a QGroundControl plan: the text is not JSON (")
        e.message ==~ /.*, at line \d+\)/
        !e.message.contains('\n')
    }

    def "an error inside a file names the file before what is wrong"() {
        given:
        Path f = file('short.waypoints', "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t40.4\t-7.3\t820\n".getBytes(StandardCharsets.UTF_8))

        when:
        WaypointsFile.read(f)

        then:
        def e = thrown(IllegalArgumentException)
        e.message == "${f}: line 2: expected 12 tab-separated fields (INDEX CURRENT FRAME COMMAND P1 P2 P3 P4 LAT LON ALT AUTOCONTINUE), found 11".toString()
    }
}
