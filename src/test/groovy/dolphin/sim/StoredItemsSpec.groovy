package dolphin.sim

import com.MAVLink.common.msg_file_transfer_protocol
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import dolphin.core.Position
import dolphin.mavlink.ftp.FileCrc32
import dolphin.mission.transfer.MissionFtpFile
import dolphin.mission.transfer.StoredItems
import spock.lang.Specification

import static dolphin.sim.RecordingConformanceSpec.DIRECTORY

/**
 * What a simulated vehicle gives back of the mission items it stored, as ArduPilot's AP_Mission
 * does: the missions ArduCopter SITL read back over FTP in the project's recordings, and the
 * commands whose parameters it keeps in fewer bytes than a float.
 */
class StoredItemsSpec extends Specification {

    static final int NAV = MAV_CMD.MAV_CMD_NAV_WAYPOINT
    static final float NAN = Float.NaN

    /** The bytes of each file written (WriteFile requests) or read (the ACKs of reads) in a recording, by the file's type. */
    static Map<MissionType, byte[]> files(Recording recording, boolean written) {
        List<SimFtpPacket> packets = written
                ? recording.groundStation*.message.findAll { it instanceof msg_file_transfer_protocol }
                .collect { SimFtpPacket.of(it) }.findAll { it.opcode() == SimFtpPacket.WRITE_FILE }
                : recording.vehicle.findAll { it instanceof msg_file_transfer_protocol }.collect { SimFtpPacket.of(it) }
                .findAll { it.opcode() == SimFtpPacket.ACK && it.reqOpcode() in [SimFtpPacket.READ_FILE, SimFtpPacket.BURST_READ_FILE] }
        packets.groupBy { it.session() }.values().collectEntries { List<SimFtpPacket> parts ->
            def bytes = new ByteArrayOutputStream()
            parts.sort { it.offset() }.each { bytes.write(it.data(), 0, it.size()) }
            byte[] file = bytes.toByteArray()
            [(MissionFtpFile.decode(file).type()): file]
        }
    }

    def "#recording: the mission ArduCopter read back is the one written as StoredItems keeps it"() {
        given:
        def recorded = Recording.read(DIRECTORY.resolve(recording + '.tlog'))
        def written = MissionFtpFile.decode(files(recorded, true)[MissionType.MISSION]).items()
        def read = MissionFtpFile.decode(files(recorded, false)[MissionType.MISSION]).items()

        expect: 'item 0 is the vehicle\'s home, set by DO_SET_HOME (SimVehicleSpec)'
        read.size() == count
        read.drop(1) == written.drop(1).collect { StoredItems.missionItem(it, false) }

        and: 'the recording holds what this spec is about'
        written.drop(1).any { Float.isNaN(it.param4()) && it.frame() == MAV_FRAME.MAV_FRAME_GLOBAL_INT }
        written.drop(1)*.command().containsAll(commands)

        where:
        recording           | count || commands
        'copter-ftp-fence'  | 5     || [MAV_CMD.MAV_CMD_NAV_TAKEOFF, NAV, MAV_CMD.MAV_CMD_NAV_LAND]
        'copter-ftp-survey' | 25    || [MAV_CMD.MAV_CMD_NAV_TAKEOFF, NAV, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, MAV_CMD.MAV_CMD_NAV_LAND]
    }

    def "#recording: the file ArduCopter read back is, byte for byte, the one an upload predicts from what it wrote and the home"() {
        given: 'the home as HOME_POSITION reports it: degE7 and whole millimetres'
        def recorded = Recording.read(DIRECTORY.resolve(recording + '.tlog'))
        byte[] readBack = files(recorded, false)[MissionType.MISSION]
        def written = MissionFtpFile.decode(files(recorded, true)[MissionType.MISSION]).items()
        def home = MissionFtpFile.decode(readBack).items()[0]
        Position reported = Position.fromDegrees(home.x() * 1e-7, home.y() * 1e-7, Math.round(home.z() * 1000) / 1000d)

        expect:
        StoredItems.file(MissionType.MISSION, written, reported, false) == readBack
        FileCrc32.of(StoredItems.file(MissionType.MISSION, written, reported, false)) == FileCrc32.of(readBack)

        where:
        recording << ['copter-ftp-fence', 'copter-ftp-survey']
    }

    def "#command (#params, frame #frame, z #z) comes back as #expected, frame #reported, x y z #xyz on #vehicle"() {
        given:
        def item = new MissionItem(3, command, frame, params[0], params[1], params[2], params[3], 404442336, -73752344, z, false)

        when:
        def back = StoredItems.missionItem(item, vehicle == 'plane')

        then:
        [back.param1(), back.param2(), back.param3(), back.param4()] == expected*.floatValue()
        back.frame() == reported
        [back.x(), back.y(), back.z()] == xyz
        back.seq() == 3
        back.command() == command
        back.autocontinue()

        where:
        command                                | params                  | frame                                        | z      | vehicle  || expected            | reported                                    | xyz
        NAV                                    | [2.7, 50, 1, NAN]       | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [2, 0, 0, 0]        | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 850f]
        NAV                                    | [2, 50.6, 300, NAN]     | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT  | 30     | 'plane'  || [0, 50, 255, 0]     | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT     | [404442336, -73752344, 30f]
        NAV                                    | [0, 0, 0, 0]            | MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT   | 12.345 | 'copter' || [0, 0, 0, 0]        | MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT      | [404442336, -73752344, 12.34f]
        NAV                                    | [0, 0, 0, 0]            | MAV_FRAME.MAV_FRAME_MISSION                  | 20     | 'copter' || [0, 0, 0, 0]        | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 20f]
        MAV_CMD.MAV_CMD_NAV_TAKEOFF            | [15, 1, 2, NAN]         | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [15, 0, 0, 0]       | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 850f]
        MAV_CMD.MAV_CMD_NAV_LAND               | [0, 0, 0, NAN]          | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 820    | 'copter' || [0, 0, 0, 1]        | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 820f]
        MAV_CMD.MAV_CMD_NAV_LAND               | [5, 0, 0, -2]           | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 820    | 'copter' || [5, 0, 0, -1]       | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 820f]
        MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM       | [0, 0, -60.5, NAN]      | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [0, 0, -60, 0]      | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 850f]
        MAV_CMD.MAV_CMD_NAV_LOITER_TURNS       | [2.7, 0, -40, 1]        | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [2, 0, -40, 1]      | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 850f]
        MAV_CMD.MAV_CMD_NAV_LOITER_TURNS       | [0.5, 0, 1234, 0]       | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [0.5, 0, 1230, 0]   | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 850f]
        MAV_CMD.MAV_CMD_NAV_LOITER_TIME        | [30.9, 5, 0, -1]        | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [30, 0, 1, 0]       | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 850f]
        MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT      | [0, -80, 0, 1]          | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [0, -80, 0, 1]      | MAV_FRAME.MAV_FRAME_GLOBAL                  | [404442336, -73752344, 850f]
        MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST  | [7.34375, 0, 1, 0]      | MAV_FRAME.MAV_FRAME_MISSION                  | 0      | 'copter' || [7.34375, 0, 1, 0]  | MAV_FRAME.MAV_FRAME_GLOBAL                  | [0, 0, 0f]
        MAV_CMD.MAV_CMD_DO_CHANGE_SPEED        | [1, 5.5, -1, 9]         | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [1, 5.5, -1, 0]     | MAV_FRAME.MAV_FRAME_GLOBAL                  | [0, 0, 0f]
        MAV_CMD.MAV_CMD_DO_JUMP                | [3, -1, 7, 7]           | MAV_FRAME.MAV_FRAME_MISSION                  | 0      | 'copter' || [3, -1, 0, 0]       | MAV_FRAME.MAV_FRAME_GLOBAL                  | [0, 0, 0f]
        MAV_CMD.MAV_CMD_CONDITION_YAW          | [90.5, 10, -1, 1]       | MAV_FRAME.MAV_FRAME_MISSION                  | 0      | 'copter' || [90.5, 10, -1, 1]   | MAV_FRAME.MAV_FRAME_GLOBAL                  | [0, 0, 0f]
        MAV_CMD.MAV_CMD_DO_SET_SERVO           | [9, 1500.7, 0, 0]       | MAV_FRAME.MAV_FRAME_MISSION                  | 0      | 'copter' || [9, 1500, 0, 0]     | MAV_FRAME.MAV_FRAME_GLOBAL                  | [0, 0, 0f]
        MAV_CMD.MAV_CMD_DO_MOUNT_CONTROL       | [-45, 0, 10, 3]         | MAV_FRAME.MAV_FRAME_MISSION                  | 0      | 'copter' || [-45, 0, 10, 0]     | MAV_FRAME.MAV_FRAME_GLOBAL                  | [0, 0, 2f]
        MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH   | [1, 2, 3, 4]            | MAV_FRAME.MAV_FRAME_GLOBAL_INT               | 850    | 'copter' || [0, 0, 0, 0]        | MAV_FRAME.MAV_FRAME_GLOBAL                  | [0, 0, 0f]
        MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF       | [1, 2, 3, NAN]          | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT  | 30     | 'plane'  || [0, 0, 0, 0]        | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT     | [404442336, -73752344, 30f]
        MAV_CMD.MAV_CMD_NAV_VTOL_LAND          | [1.7, 2, NAN, NAN]      | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT  | 0      | 'plane'  || [1, 0, 0, 0]        | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT     | [404442336, -73752344, 0f]
        MAV_CMD.MAV_CMD_DO_VTOL_TRANSITION     | [4, 1, 2, 3]            | MAV_FRAME.MAV_FRAME_MISSION                  | 0      | 'plane'  || [4, 0, 0, 0]        | MAV_FRAME.MAV_FRAME_GLOBAL                  | [0, 0, 0f]
    }

    def "CONDITION_CHANGE_ALT, which AP_Mission does not know, is UNSUPPORTED"() {
        expect:
        MissionCheck.result(MissionItem.command(1, MAV_CMD.MAV_CMD_CONDITION_CHANGE_ALT, 1, 0, 0, 10), false) ==
                MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED
    }
}
