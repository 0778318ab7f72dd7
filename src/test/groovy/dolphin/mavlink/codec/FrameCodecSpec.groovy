package dolphin.mavlink.codec

import com.MAVLink.standard.msg_global_position_int
import com.MAVLink.common.msg_mission_item_int
import com.MAVLink.common.msg_sys_status
import com.MAVLink.minimal.msg_heartbeat
import spock.lang.Specification

import static dolphin.mavlink.codec.DropCounters.Reason.*

class FrameCodecSpec extends Specification {

    static heartbeat(long mode = 3) {
        new msg_heartbeat(custom_mode: mode, type: 2, autopilot: 3, base_mode: 217, system_status: 4, mavlink_version: 3)
    }

    static item(int seq) {
        new msg_mission_item_int(seq: seq, command: 16, frame: 5, x: 401234567, y: -73456789, z: 820.5f,
                param1: 0, param2: 2, param3: 0, param4: Float.NaN, target_system: 1, target_component: 1, autocontinue: 1)
    }

    static byte[] cat(byte[]... parts) {
        def out = new ByteArrayOutputStream()
        parts.each { out.write(it) }
        out.toByteArray()
    }

    /** Feeds the chunks as one datagram. (No varargs: Groovy would spread a lone byte[] into one-byte arrays.) */
    static List<Frame> read(FrameReader r, List<byte[]> chunks) {
        List<Frame> out = []
        chunks.each { byte[] chunk -> r.feed(chunk, 0, chunk.length, { out << it }) }
        r.endOfPacket({ out << it })
        out
    }

    static List<Frame> read(FrameReader r, byte[] datagram) {
        read(r, [datagram])
    }

    /** Feeds a stream one byte at a time, with no datagram boundary. */
    static List<Frame> trickle(FrameReader r, byte[] stream) {
        List<Frame> out = []
        stream.each { byte b -> r.feed([b] as byte[], 0, 1, { out << it }) }
        out
    }

    def "a written frame reads back with the same header and message"() {
        given:
        def w = new FrameWriter(208, 190)

        when:
        def frames = read(new FrameReader(), [w.write(item(7)), w.write(heartbeat())])

        then:
        frames*.msgid == [73, 0]
        frames*.seq == [0, 1]
        frames.every { it.version == 2 && it.sysid == 208 && it.compid == 190 && it.verified && !it.signed() }
        with(frames[0].message() as msg_mission_item_int) {
            seq == 7 && command == 16 && frame == 5 && x == 401234567 && y == -73456789 && z == 820.5f && Float.isNaN(param4)
        }
        (frames[1].message() as msg_heartbeat).custom_mode == 3
    }

    def "the sequence number wraps after 255"() {
        given:
        def w = new FrameWriter(1, 1)
        257.times { w.write(heartbeat()) }

        expect:
        read(new FrameReader(), w.write(heartbeat()))[0].seq == 1
    }

    def "trailing zeros of the payload are truncated and read back as zeros"() {
        given:
        def status = new msg_sys_status(voltage_battery: 12600, battery_remaining: 0 as byte)

        when:
        byte[] bytes = new FrameWriter(1, 1).write(status)
        def frame = read(new FrameReader(), bytes)[0]

        then: 'SYS_STATUS is 43 bytes; everything after voltage_battery (offset 14, 2 bytes) is zero'
        bytes[1] == 16
        frame.payload.length == 16
        with(frame.message() as msg_sys_status) {
            voltage_battery == 12600 && battery_remaining == 0 && current_battery == 0
        }
    }

    def "an all-zero payload keeps one byte"() {
        expect:
        new FrameWriter(1, 1).write(new msg_heartbeat())[1] == 1
    }

    def "frames split at every possible point are reassembled"() {
        given:
        def w = new FrameWriter(1, 1)
        byte[] stream = cat(w.write(heartbeat()), w.write(item(1)), w.write(heartbeat(4)))

        expect:
        (1..<stream.length).every { cut ->
            def frames = read(new FrameReader(), [Arrays.copyOfRange(stream, 0, cut), Arrays.copyOfRange(stream, cut, stream.length)])
            frames*.msgid == [0, 73, 0]
        }
    }

    def "garbage between frames is skipped and counted in bytes"() {
        given:
        def w = new FrameWriter(1, 1)
        def r = new FrameReader()
        byte[] junk = [1, 2, 3, 0xFD, 9, 0, 0] as byte[]

        when:
        def frames = read(r, cat(junk, w.write(heartbeat()), [0x55, 0xFE, 0x01] as byte[], w.write(item(2))))

        then:
        frames*.msgid == [0, 73]
        r.drops().get(GARBAGE_BYTES) > 0
    }

    def "a frame with a bad checksum is dropped, counted, and the next frame is still found"() {
        given:
        def w = new FrameWriter(1, 1)
        byte[] bad = w.write(heartbeat())
        bad[12] ^= 0x40
        def r = new FrameReader()

        when:
        def frames = read(r, cat(bad, w.write(heartbeat(5))))

        then:
        frames.size() == 1
        (frames[0].message() as msg_heartbeat).custom_mode == 5
        r.drops().get(BAD_CRC) == 1
    }

    def "on a stream, an unknown id waits for the next byte before it is taken for a frame"() {
        given:
        def w = new FrameWriter(1, 1)
        byte[] junk = [1, 2, 3, 0xFD, 9, 0, 0] as byte[]
        def r = new FrameReader()

        expect: 'fed byte by byte, the false start before the heartbeat does not swallow it'
        trickle(r, cat(junk, w.write(heartbeat()), w.write(heartbeat(4))))*.msgid == [0, 0]
        r.drops().get(UNVERIFIABLE) == 1
    }

    def "on a stream, an unknown id does not swallow a frame that starts inside it and has not fully arrived"() {
        given: 'a false start whose 14 bytes end inside the heartbeat after it, on a 0xFE payload byte'
        def w = new FrameWriter(1, 1)
        byte[] junk = [0xFD, 2, 0, 0] as byte[]
        byte[] frame = w.write(heartbeat(0xFFFFFFFEL))
        def r = new FrameReader()

        expect: 'the false start is an unknown id (0x010000) followed by a start byte'
        frame[10] == (byte) 0xFE
        (frame[3] & 0xFF | (frame[4] & 0xFF) << 8 | (frame[5] & 0xFF) << 16) == 0x010000

        and: 'fed byte by byte, the heartbeat is recovered, and so is the next one'
        trickle(r, cat(junk, frame, w.write(heartbeat(4))))*.msgid == [0, 0]
        r.drops().get(UNVERIFIABLE) == 1
    }

    def "a frame that starts inside a corrupted frame is recovered"() {
        given: 'a frame whose length byte claims more bytes than it has, swallowing the next frame'
        def w = new FrameWriter(1, 1)
        byte[] first = w.write(heartbeat())
        first[1] = 40
        def r = new FrameReader()

        when:
        def frames = read(r, cat(first, w.write(heartbeat(6)), w.write(heartbeat(7)), new byte[40]))

        then:
        frames.collect { (it.message() as msg_heartbeat).custom_mode } == [6L, 7L]
    }

    def "MAVLink 1 frames are read"() {
        given: 'a MAVLink 1 heartbeat from the generated packer'
        def hb = heartbeat(10)
        hb.isMavlink2 = false
        hb.sysid = 3
        hb.compid = 1
        byte[] v1 = hb.pack().encodePacket()

        when:
        def frames = read(new FrameReader(), v1)

        then:
        v1[0] == (byte) 0xFE
        frames.size() == 1
        frames[0].version == 1
        frames[0].sysid == 3
        (frames[0].message() as msg_heartbeat).custom_mode == 10
    }

    def "an unknown message id is kept as a raw, unverified frame when it stands alone"() {
        given:
        byte[] unknown = [0xFD, 2, 0, 0, 9, 1, 1, 0x39, 0x30, 0, 0xAA, 0xBB, 0x12, 0x34] as byte[]

        when:
        def frames = read(new FrameReader(), cat(unknown, new FrameWriter(1, 1).write(heartbeat())))

        then:
        frames*.msgid == [0x3039, 0]
        !frames[0].verified
        frames[0].message() == null
        frames[0].raw == unknown
        frames[0].payload == [0xAA, 0xBB] as byte[]
    }

    def "a frame with an unknown incompatibility flag is dropped and counted"() {
        given:
        def w = new FrameWriter(1, 1)
        byte[] f = w.write(heartbeat())
        f[2] = 0x02
        int crc = X25.accumulate(X25.accumulate(X25.SEED, f, 1, 9 + f[1]), 50)
        f[10 + f[1]] = (byte) crc
        f[11 + f[1]] = (byte) (crc >>> 8)
        def r = new FrameReader()

        when:
        def frames = read(r, cat(f, w.write(heartbeat())))

        then:
        frames.size() == 1
        r.drops().get(UNKNOWN_INCOMPAT_FLAGS) == 1
    }

    def "with a key, signed frames pass and unsigned, wrongly signed and replayed ones are dropped and counted"() {
        given:
        def key = SigningKey.fromPassphrase('dolphin')
        def other = SigningKey.fromPassphrase('not dolphin')
        def signer = new FrameWriter(1, 1, key, 0)
        def r = new FrameReader(key, new DropCounters())
        byte[] good = signer.write(heartbeat(1))

        when:
        def frames = read(r, [good, new FrameWriter(1, 1).write(heartbeat(2)), new FrameWriter(1, 1, other, 0).write(heartbeat(3)),
                good, signer.write(heartbeat(4))])

        then:
        frames.collect { (it.message() as msg_heartbeat).custom_mode } == [1L, 4L]
        frames.every { it.signed() && it.linkId() == 0 && it.signatureTimestamp() > 0 }
        r.drops().get(UNSIGNED) == 1
        r.drops().get(BAD_SIGNATURE) == 1
        r.drops().get(REPLAYED) == 1
        r.drops().frames() == 3
    }

    def "without a key, signed frames are read too"() {
        expect:
        read(new FrameReader(), new FrameWriter(1, 1, SigningKey.fromPassphrase('k'), 3).write(heartbeat()))[0].linkId() == 3
    }

    def "a position message survives a round trip with negative values"() {
        given:
        def pos = new msg_global_position_int(lat: -401234567, lon: 73456789, alt: -12345, relative_alt: 5000, vx: -5 as short, hdg: 35999)

        when:
        def m = read(new FrameReader(), new FrameWriter(2, 1).write(pos))[0].message() as msg_global_position_int

        then:
        m.lat == -401234567 && m.lon == 73456789 && m.alt == -12345 && m.relative_alt == 5000 && m.vx == -5 && m.hdg == 35999
    }
}
