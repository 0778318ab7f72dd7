package dolphin.sim

import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_file_transfer_protocol
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_PROTOCOL_CAPABILITY
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.standard.msg_autopilot_version
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import dolphin.mission.transfer.MissionFtpFile
import spock.lang.Specification

import java.nio.ByteBuffer
import java.nio.ByteOrder

import static dolphin.sim.MissionProtocolSpec.plan
import static dolphin.sim.MissionProtocolSpec.rel
import static dolphin.sim.SimFtpPacket.*

/**
 * A simulated vehicle's MAVLink FTP server on a fake clock, no sockets: its @MISSION files read and
 * written as ArduPilot's GCS_FTP and AP_Filesystem_Mission serve them; AUTOPILOT_VERSION with and
 * without FTP.
 */
class SimFtpServerSpec extends Specification {

    static final String MISSION = '@MISSION/mission.dat'

    SimDriver d = new SimDriver(VehicleKind.COPTER)

    /** A request to vehicle 1: data a path or bytes; size (the data's length unless given), offset, session. */
    static def ftpRequest(int seq, int opcode, Map fields = [:]) {
        byte[] data = fields.data instanceof String ? (fields.data as String).getBytes('ISO-8859-1') : (fields.data ?: new byte[0]) as byte[]
        int size = fields.containsKey('size') ? fields.size as int : data.length
        def m = new msg_file_transfer_protocol(target_system: 1, target_component: 1)
        def header = ByteBuffer.allocate(12).order(ByteOrder.LITTLE_ENDIAN)
        header.putShort((short) seq).put((byte) (fields.session ?: 0)).put((byte) opcode).put((byte) size).put((byte) 0)
                .put((byte) 0).put((byte) 0).putInt((fields.offset ?: 0) as int)
        ((header.array() as List) + (data as List)).eachWithIndex { b, i -> m.payload[i] = (short) (b & 0xff) }
        m
    }

    /** Sends one request from (255, 190); the replies it got. */
    List<SimFtpPacket> ftp(int seq, int opcode, Map fields = [:]) {
        int from = d.mark()
        d.handle(ftpRequest(seq, opcode, fields), 255, 190)
        d.since(from, msg_file_transfer_protocol).collect { SimFtpPacket.of(it) }
    }

    static int naked(SimFtpPacket p) {
        assert p.opcode() == NAK
        p.data()[0]
    }

    static List<MissionItem> hundred() {
        [plan()[0]] + (1..99).collect { rel(it, MAV_CMD.MAV_CMD_NAV_WAYPOINT, it * 10, it % 7, 20 + it % 5) }
    }

    /** Writes the file in 80-byte blocks, the ones in {@code skip} left out, then closes it: the close's replies. */
    List<SimFtpPacket> writeFile(byte[] file, String path = MISSION, Set<Integer> skip = [] as Set) {
        assert ftp(1, CREATE_FILE, [data: path, session: 3])[0].opcode() == ACK
        int seq = 2
        for (int at = 0; at < file.length; at += 80) {
            if (!(at.intdiv(80) in skip)) {
                def reply = ftp(seq, WRITE_FILE, [data: Arrays.copyOfRange(file, at, Math.min(file.length, at + 80)), offset: at, session: 3])
                assert reply*.opcode() == [ACK] && reply[0].offset() == at
            }
            seq += 2
        }
        ftp(seq, TERMINATE_SESSION, [session: 3])
    }

    def "OpenFileRO of the mission: ACK with size 1,048,576, the client's session echoed, seq + 1, to the requester"() {
        when:
        def replies = ftp(41, OPEN_FILE_RO, [data: MISSION, session: 7])

        then:
        replies.size() == 1
        with(replies[0]) {
            opcode() == ACK
            reqOpcode() == OPEN_FILE_RO
            session() == 7
            seq() == 42
            size() == 4
            ByteBuffer.wrap(data(), 0, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() == 1_048_576
        }
        with(d.sent.last().message as msg_file_transfer_protocol) {
            target_system == 255
            target_component == 190
        }
    }

    def "a burst read of a 100-item mission: 239-byte ACKs, the last short with burst_complete, then NAK EOF; decoded back as a download reports it"() {
        given:
        def items = hundred()
        assert d.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        ftp(1, OPEN_FILE_RO, [data: MISSION])

        when:
        def replies = ftp(2, BURST_READ_FILE, [size: 239])
        def acks = replies.findAll { it.opcode() == ACK }
        int length = MissionFtpFile.HEADER_BYTES + 100 * MissionFtpFile.ITEM_BYTES

        then:
        acks.size() == Math.ceil(length / 239) as int
        acks*.reqOpcode().every { it == BURST_READ_FILE }
        acks*.seq() == (3..<3 + acks.size()).toList()
        acks*.offset() == (0..<acks.size()).collect { it * 239L }
        acks.dropRight(1).every { it.size() == 239 && !it.burstComplete() }
        acks.last().size() == length % 239
        acks.last().burstComplete()

        and: 'a NAK EOF at the end closes the burst'
        naked(replies.last()) == EOF
        replies.last().offset() == length
        replies.last().seq() == acks.last().seq() + 1

        and:
        byte[] file = acks.collectMany { Arrays.copyOf(it.data(), it.size()) as List } as byte[]
        def contents = MissionFtpFile.decode(file)
        contents.type() == MissionType.MISSION
        contents.items().size() == 100
        contents.items().drop(1) == items.drop(1).collect {
            new MissionItem(it.seq(), it.command(), MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT, it.param1(), it.param2(), it.param3(),
                    it.param4(), it.x(), it.y(), it.z(), it.autocontinue())
        }
        contents.items()[0] == d.vehicle.mission()[0]
    }

    def "a ReadFile at or past the end is NAK EOF; the lost part of a burst is read with ReadFile"() {
        given:
        assert d.upload(plan()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        ftp(1, OPEN_FILE_RO, [data: MISSION])
        int length = MissionFtpFile.HEADER_BYTES + 6 * MissionFtpFile.ITEM_BYTES

        expect:
        with(ftp(2, READ_FILE, [size: 100, offset: 200])[0]) {
            opcode() == ACK && size() == length - 200 && offset() == 200
        }
        naked(ftp(4, READ_FILE, [size: 100, offset: length])[0]) == EOF
        naked(ftp(6, READ_FILE, [size: 100, offset: 5000])[0]) == EOF
    }

    def "a repeated request gets the same reply again; the next seq a new one"() {
        given:
        assert d.upload(plan()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        ftp(1, OPEN_FILE_RO, [data: MISSION])
        def first = ftp(2, READ_FILE, [size: 239, offset: 0])

        when: 'the mission changes, then the same request comes again'
        assert d.upload(plan().take(3)) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        def again = ftp(2, READ_FILE, [size: 239, offset: 0])
        def next = ftp(4, READ_FILE, [size: 239, offset: 0])

        then:
        again.size() == 1
        again[0].seq() == 3
        again[0].data() == first[0].data()
        again[0].size() == first[0].size()
        next[0].size() == MissionFtpFile.HEADER_BYTES + 3 * MissionFtpFile.ITEM_BYTES
    }

    def "CreateFile, WriteFile in 80-byte blocks, TerminateSession: the mission stored as an upload would store it, and nothing said"() {
        given:
        def items = hundred()
        int from = d.mark()

        when:
        def close = writeFile(MissionFtpFile.encode(MissionType.MISSION, items))

        then:
        close*.opcode() == [ACK]
        d.vehicle.mission().drop(1) == items.drop(1)
        d.vehicle.mission()[0].x() == MissionItem.degE7(SimDriver.HOME.latitudeDegrees())
        d.since(from, msg_statustext).isEmpty()
    }

    def "a close with a block never written is NAK FailErrno EINVAL, the stored mission untouched; repeated with its seq the same NAK, with a new seq an ACK"() {
        given:
        def old = plan()
        assert d.upload(old) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED

        when:
        def close = writeFile(MissionFtpFile.encode(MissionType.MISSION, hundred()), MISSION, [20] as Set)
        int closeSeq = 2 + 2 * Math.ceil((MissionFtpFile.HEADER_BYTES + 100 * MissionFtpFile.ITEM_BYTES) / 80) as int

        then:
        naked(close[0]) == FAIL_ERRNO
        close[0].data()[1] == 22
        close[0].size() == 2
        d.vehicle.mission().drop(1) == old.drop(1)

        and:
        ftp(closeSeq, TERMINATE_SESSION, [session: 3])[0].opcode() == NAK
        ftp(closeSeq + 2, TERMINATE_SESSION, [session: 3])[0].opcode() == ACK
    }

    def "a close with a refused item: cleared first, the items before it stored, as ArduPilot leaves it"() {
        given:
        assert d.upload(hundred()) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        def items = plan()
        items[3] = MissionItem.command(3, MAV_CMD.MAV_CMD_DO_CHANGE_ALTITUDE, 30, 0, 0, 0)

        when:
        def close = writeFile(MissionFtpFile.encode(MissionType.MISSION, items))

        then:
        naked(close[0]) == FAIL_ERRNO
        close[0].data()[1] == 22
        d.vehicle.mission().drop(1) == items.subList(1, 3)
    }

    def "a DO_JUMP to item 0 or past the file's count is refused at the close"() {
        given:
        def items = plan()
        items[2] = MissionItem.command(2, MAV_CMD.MAV_CMD_DO_JUMP, 6, 1, 0, 0)

        expect:
        naked(writeFile(MissionFtpFile.encode(MissionType.MISSION, items))[0]) == FAIL_ERRNO
        d.vehicle.mission().size() == 2
    }

    def "fence and rally files: stored whole; NO_CLEAR refused"() {
        given:
        def rally = [new MissionItem(0, MAV_CMD.MAV_CMD_NAV_RALLY_POINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0, 0,
                404440000, -73750000, 30, false)]
        byte[] file = MissionFtpFile.encode(MissionType.RALLY, rally)

        expect:
        writeFile(file, '@MISSION/rally.dat')[0].opcode() == ACK
        d.vehicle.rallyPoints().items().size() == 1

        when:
        file[4] = 1
        def close = writeFile(file, '@MISSION/rally.dat')

        then:
        naked(close[0]) == FAIL_ERRNO
    }

    def "five sessions, four open files: a fifth open is ENFILE, a sixth session NoSessionsAvailable until one has been idle 3 s; ResetSessions closes the requester's"() {
        given:
        (1..4).each { assert ftp(1, OPEN_FILE_RO, [data: MISSION, session: it])[0].opcode() == ACK }

        expect: 'the fifth session is taken, but AP_Filesystem_Mission has four files'
        def fifth = ftp(1, OPEN_FILE_RO, [data: MISSION, session: 5])[0]
        naked(fifth) == FAIL_ERRNO
        fifth.data()[1] == 23
        naked(ftp(1, OPEN_FILE_RO, [data: MISSION, session: 6])[0]) == NO_SESSIONS_AVAILABLE

        when:
        d.run(3.1)

        then:
        ftp(3, OPEN_FILE_RO, [data: MISSION, session: 6])[0].opcode() == ACK

        when: 'the client resets its sessions'
        def reset = ftp(9, RESET_SESSIONS)

        then:
        reset*.opcode() == [ACK]
        reset[0].seq() == 10
        naked(ftp(11, READ_FILE, [size: 10, session: 6])[0]) == FILE_NOT_FOUND
    }

    def "a second open on a busy session is Fail; other paths FileNotFound; TruncateFile and unknown opcodes Fail; a bad name length InvalidDataSize"() {
        given:
        ftp(1, OPEN_FILE_RO, [data: MISSION])

        expect:
        naked(ftp(3, OPEN_FILE_RO, [data: MISSION])[0]) == FAIL
        naked(ftp(5, OPEN_FILE_RO, [data: '@MISSION/foo.dat', session: 1])[0]) == FILE_NOT_FOUND
        naked(ftp(7, OPEN_FILE_RO, [data: '@PARAM/param.pck', session: 1])[0]) == FILE_NOT_FOUND
        naked(ftp(9, CREATE_FILE, [data: 'log.txt', session: 1])[0]) == FILE_NOT_FOUND
        naked(ftp(11, 12)[0]) == FAIL
        naked(ftp(13, 99)[0]) == FAIL
        naked(ftp(15, OPEN_FILE_RO, [data: MISSION, size: 3, session: 2])[0]) == INVALID_DATA_SIZE
        ftp(17, NONE)[0].opcode() == ACK
    }

    def "an upload left open is loaded once its session has been idle 20 s, as ArduPilot's worker closes it"() {
        given:
        def items = plan()
        byte[] file = MissionFtpFile.encode(MissionType.MISSION, items)
        ftp(1, CREATE_FILE, [data: MISSION, session: 3])
        ftp(2, WRITE_FILE, [data: file, offset: 0, session: 3]) // 238 bytes: one write

        when:
        d.run(19.9)
        def before = d.vehicle.mission().size()
        d.run(0.2)

        then:
        before == 1
        d.vehicle.mission().drop(1) == items.drop(1)
    }

    def "a vehicle without FTP answers no FILE_TRANSFER_PROTOCOL at all"() {
        given:
        d = new SimDriver(VehicleKind.COPTER, SimOptions.DEFAULT.withoutFtp())

        expect:
        ftp(1, OPEN_FILE_RO, [data: MISSION]).isEmpty()
        ftp(2, RESET_SESSIONS).isEmpty()
        d.sent.findAll { it.message instanceof msg_file_transfer_protocol }.isEmpty()
    }

    def "AUTOPILOT_VERSION for #kind (FTP #ftp): COMMAND_ACK ACCEPTED, then capabilities #capabilities, asked with #command"() {
        given:
        d = new SimDriver(kind, ftp ? SimOptions.DEFAULT : SimOptions.DEFAULT.withoutFtp())
        int from = d.mark()

        when:
        def ack = command == 512 ? d.command(MAV_CMD.MAV_CMD_REQUEST_MESSAGE, [148]) : d.command(MAV_CMD.MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES, [1])

        then:
        ack.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        def versions = d.since(from, msg_autopilot_version)
        versions.size() == 1
        versions[0].capabilities == capabilities
        ((versions[0].capabilities & MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_FTP) != 0) == ftp
        d.indexOf(from) { it instanceof msg_command_ack } < d.indexOf(from) { it instanceof msg_autopilot_version }

        where: 'as ArduPilot 64a9c78 SITL reported them (plane: from its GCS_MAVLINK_Plane::capabilities())'
        kind               | ftp   | command || capabilities
        VehicleKind.COPTER | true  | 520     || 64495
        VehicleKind.COPTER | true  | 512     || 64495
        VehicleKind.COPTER | false | 520     || 64495 - 32
        VehicleKind.ROVER  | true  | 520     || 61935
        VehicleKind.SUB    | true  | 512     || 63975
        VehicleKind.PLANE  | true  | 520     || 62319
    }

    def "MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES with p1 other than 1 is FAILED, and nothing sent"() {
        given:
        int from = d.mark()

        expect:
        d.command(MAV_CMD.MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES, [0]).result == MAV_RESULT.MAV_RESULT_FAILED
        d.since(from, msg_autopilot_version).isEmpty()
    }
}
