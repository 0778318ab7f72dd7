package dolphin.mission.file

import dolphin.mission.model.MissionItem
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import spock.lang.Specification

import static MissionFileFixtures.*

class WaypointsFileSpec extends Specification {

    def "export then import gives the same items, NaN parameters included"() {
        when:
        def back = WaypointsFile.read(WaypointsFile.write(items))

        then:
        back == items

        where:
        items << [mission(), extremes(), random(1, 40), random(2, 40), random(3, 200)]
    }

    def "the first line is the header, then one line per item with 12 tab-separated fields"() {
        when:
        def lines = WaypointsFile.write(mission()).split('\n', -1) as List

        then:
        lines[0] == 'QGC WPL 110'
        lines.last() == ''
        lines.size() == 1 + mission().size() + 1
        lines[1..-2].every { it.split('\t', -1).size() == 12 && !it.contains(' ') }
        lines[1..-2].collect { it.split('\t')[0] as int } == (0..<mission().size()).toList()
    }

    def "line 0 is the home: current 1, float frame GLOBAL, exact degrees and AMSL altitude"() {
        when:
        def f = WaypointsFile.write(mission()).split('\n')[1].split('\t')

        then:
        f == ['0', '1', '0', '16', '0', '0', '0', '0', '40.4442330', '-7.3752340', '820', '1'] as String[]
    }

    def "items: CURRENT 0, frames as files name them, nan for NaN, shortest decimals"() {
        when:
        def lines = WaypointsFile.write(mission()).split('\n')

        then: 'take-off: pitch 15, yaw NaN'
        lines[2].split('\t') == ['1', '0', '0', '22', '15', '0', '0', 'nan', '40.4442330', '-7.3752340', '1200', '1'] as String[]

        and: 'DO_CHANGE_SPEED has no position: MAV_FRAME_MISSION (2), x and y 0'
        lines[4].split('\t') == ['3', '0', '2', '178', '0', '12.5', '-1', '0', '0.0000000', '0.0000000', '0', '1'] as String[]

        and: 'a float parameter is written as the float, not as its double expansion'
        lines[5].split('\t')[6] == '0.1'
    }

    def "the _INT frames are written as the float frames and read back as the _INT frames"() {
        given:
        def items = [new MissionItem(0, 16, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 0, 0, 0, 0, 1, 2, 3, true),
                     new MissionItem(1, 16, itemFrame, 0, 0, 0, 0, 1, 2, 3, true)]

        when:
        def text = WaypointsFile.write(items)

        then:
        text.split('\n')[2].split('\t')[2] as int == fileFrame
        WaypointsFile.read(text)[1].frame() == itemFrame

        where:
        itemFrame                                    | fileFrame
        MAV_FRAME.MAV_FRAME_GLOBAL_INT               | MAV_FRAME.MAV_FRAME_GLOBAL
        MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT  | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT
        MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT   | MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT
        MAV_FRAME.MAV_FRAME_MISSION                  | MAV_FRAME.MAV_FRAME_MISSION
    }

    def "negative zero, the smallest float and the largest float survive"() {
        when:
        def back = WaypointsFile.read(WaypointsFile.write(extremes()))[1]

        then:
        Float.floatToRawIntBits(back.param1()) == Float.floatToRawIntBits(-0.0f)
        back.param2() == 1e-7f
        back.param3() == Float.MAX_VALUE
        back.param4() == Float.MIN_VALUE
        !back.autocontinue()
    }

    def "reads files that Mission Planner and mavwp write: CRLF, %f precision, comments, a command-0 home"() {
        given:
        def text = 'QGC WPL 110\r\n' +
                '0\t1\t0\t0\t0.000000\t0.000000\t0.000000\t0.000000\t-35.363262\t149.165237\t584.090000\t1\r\n' +
                '# a comment line, as mavwp writes them\r\n' +
                '\r\n' +
                '1\t0\t3\t16\t0.000000\t0.000000\t0.000000\t0.000000\t-35.361354\t149.163283\t100.000000\t1\r\n' +
                '7 0 3 22 NaN 0 0 nan -35.3613540 149.1632830 1.5e2 0\r\n'

        when:
        def items = WaypointsFile.read(text)

        then:
        items.size() == 3
        items*.seq() == [0, 1, 2]
        items[0] == new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_INT, 0, 0, 0, 0,
                -353632620, 1491652370, 584.09f, true)
        items[1].frame() == MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
        items[1].x() == -353613540
        items[2].command() == MAV_CMD.MAV_CMD_NAV_TAKEOFF
        items[2].param1().isNaN()
        items[2].param4().isNaN()
        items[2].z() == 150f
        !items[2].autocontinue()
    }

    def "the command-0 quirk applies to the home line only"() {
        given:
        def text = 'QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t1\t2\t3\t1\n1\t0\t2\t0\t0\t0\t0\t0\t0\t0\t0\t1\n'

        expect:
        WaypointsFile.read(text)[1].command() == 0
    }

    def "a text that is not a QGC WPL 110 file is rejected with the reason"() {
        when:
        WaypointsFile.read(text)

        then:
        def e = thrown(IllegalArgumentException)
        e.message.contains(reason)

        where:
        text                                                            | reason
        ''                                                              | "the first line must be 'QGC WPL 110', the file is empty"
        'QGC WPL 100\n0 1 0 16 0 0 0 0 1 2 3 1\n'                       | "found 'QGC WPL 100'"
        '{"fileType": "Plan"}'                                          | "not a QGC WPL 110 file"
        'QGC WPL 110\n'                                                 | 'the file has no items'
        'QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t1\t2\t3\n'                  | 'line 2: expected 12 tab-separated fields'
        'QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t1\t2\t3\t1\t9\n'            | 'found 13'
        'QGC WPL 110\n0\t1\t0\t16\tx\t0\t0\t0\t1\t2\t3\t1\n'               | "line 2: 'x' is not a number"
        'QGC WPL 110\n0\t1\t0\tWAYPOINT\t0\t0\t0\t0\t1\t2\t3\t1\n'         | "line 2: 'WAYPOINT' is not an integer"
        'QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\tnorth\t2\t3\t1\n'           | "line 2: 'north' is not a number of degrees"
        'QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t1\t200\t3\t1\n'             | 'out of range'
    }

    def "exporting nothing is refused: a mission file has at least the home"() {
        when:
        WaypointsFile.write([])

        then:
        thrown(IllegalArgumentException)
    }

    def "files on disk: write then read"() {
        given:
        def file = File.createTempFile('mission', '.waypoints').toPath()

        when:
        WaypointsFile.write(file, mission())

        then:
        WaypointsFile.read(file) == mission()

        cleanup:
        file?.toFile()?.delete()
    }
}
