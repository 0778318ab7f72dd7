package dolphin.mavlink.codec;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_command_long;
import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.common.msg_mission_request;
import com.MAVLink.common.msg_statustext;
import com.MAVLink.common.msg_sys_status;
import com.MAVLink.minimal.msg_heartbeat;
import com.MAVLink.standard.msg_global_position_int;
import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;

/**
 * The reader recovers every valid frame whatever surrounds it, and never throws. The seed is fixed:
 * random garbage can, very rarely, hold a fake frame whose 16-bit checksum matches by chance.
 */
class FrameCodecProperties {

    @Property(tries = 500, seed = "20261121")
    void framesSplicedBetweenRandomBytesAreAllRecovered(@ForAll("frames") List<byte[]> frames,
                                                        @ForAll @Size(max = 12) List<@Size(max = 60) List<Byte>> garbage,
                                                        @ForAll @IntRange(min = 1, max = 64) int chunk) {
        ByteArrayOutputStream stream = new ByteArrayOutputStream();
        for (int i = 0; i < frames.size(); i++) {
            if (i < garbage.size()) {
                garbage.get(i).forEach(stream::write);
            }
            stream.writeBytes(frames.get(i));
        }
        List<byte[]> read = new ArrayList<>();
        FrameReader reader = new FrameReader();
        byte[] all = stream.toByteArray();
        for (int off = 0; off < all.length; off += chunk) {
            reader.feed(all, off, Math.min(chunk, all.length - off), f -> read.add(f.raw()));
        }
        reader.endOfPacket(f -> read.add(f.raw()));
        assertSubsequence(frames, read);
    }

    @Property(tries = 300)
    void randomInputNeverThrows(@ForAll @Size(max = 600) List<Byte> bytes, @ForAll @IntRange(min = 1, max = 300) int chunk) {
        byte[] all = new byte[bytes.size()];
        for (int i = 0; i < all.length; i++) {
            all[i] = bytes.get(i);
        }
        FrameReader reader = new FrameReader(SigningKey.fromPassphrase("k"), new DropCounters());
        FrameReader plain = new FrameReader();
        for (int off = 0; off < all.length; off += chunk) {
            int n = Math.min(chunk, all.length - off);
            reader.feed(all, off, n, f -> { });
            plain.feed(all, off, n, Frame::message);
        }
        reader.endOfPacket(f -> { });
        plain.endOfPacket(Frame::message);
    }

    @Property(tries = 200)
    void byteByByteEqualsWhole(@ForAll("frames") List<byte[]> frames) {
        ByteArrayOutputStream stream = new ByteArrayOutputStream();
        frames.forEach(stream::writeBytes);
        byte[] all = stream.toByteArray();
        List<byte[]> trickled = new ArrayList<>();
        FrameReader reader = new FrameReader();
        for (int i = 0; i < all.length; i++) {
            reader.feed(all, i, 1, f -> trickled.add(f.raw()));
        }
        assertSubsequence(frames, trickled);
        if (trickled.size() != frames.size()) {
            throw new AssertionError("expected exactly " + frames.size() + " frames, got " + trickled.size());
        }
    }

    @Provide
    Arbitrary<List<byte[]>> frames() {
        // The system id is generated too (an identity hash would make runs differ despite the fixed seed).
        return Combinators.combine(message(), Arbitraries.integers().between(1, 255))
                .as((m, sysid) -> new FrameWriter(sysid, 1).write(m)).list().ofMinSize(1).ofMaxSize(12);
    }

    private Arbitrary<MAVLinkMessage> message() {
        Arbitrary<Integer> i32 = Arbitraries.integers();
        Arbitrary<Integer> u16 = Arbitraries.integers().between(0, 65535);
        Arbitrary<Short> u8 = Arbitraries.shorts().between((short) 0, (short) 255);
        Arbitrary<Float> f = Arbitraries.floats().between(-1e6f, 1e6f);
        return Arbitraries.oneOf(
                Combinators.combine(i32, u8, u8).as((mode, type, status) -> {
                    msg_heartbeat m = new msg_heartbeat();
                    m.custom_mode = mode & 0xFFFFFFFFL;
                    m.type = type;
                    m.system_status = status;
                    m.mavlink_version = 3;
                    return m;
                }),
                Combinators.combine(u16, Arbitraries.bytes()).as((mv, pct) -> {
                    msg_sys_status m = new msg_sys_status();
                    m.voltage_battery = mv;
                    m.battery_remaining = pct;
                    return m;
                }),
                Combinators.combine(i32, i32, i32, u16).as((lat, lon, alt, hdg) -> {
                    msg_global_position_int m = new msg_global_position_int();
                    m.lat = lat;
                    m.lon = lon;
                    m.alt = alt;
                    m.hdg = hdg;
                    return m;
                }),
                Combinators.combine(u16, u16, i32, i32, f, f).as((seq, cmd, x, y, z, p1) -> {
                    msg_mission_item_int m = new msg_mission_item_int();
                    m.seq = seq;
                    m.command = cmd;
                    m.x = x;
                    m.y = y;
                    m.z = z;
                    m.param1 = p1;
                    m.frame = 5;
                    return m;
                }),
                u16.map(seq -> {
                    msg_mission_request m = new msg_mission_request();
                    m.seq = seq;
                    return m;
                }),
                Arbitraries.strings().alpha().ofMaxLength(50).map(text -> {
                    msg_statustext m = new msg_statustext();
                    m.setText(text);
                    m.severity = 6;
                    return m;
                }),
                Combinators.combine(u16, f, f).as((cmd, p1, p2) -> {
                    msg_command_long m = new msg_command_long();
                    m.command = cmd;
                    m.param1 = p1;
                    m.param2 = p2;
                    return m;
                }));
    }

    private static void assertSubsequence(List<byte[]> expected, List<byte[]> actual) {
        int j = 0;
        for (byte[] a : actual) {
            if (j < expected.size() && Arrays.equals(a, expected.get(j))) {
                j++;
            }
        }
        if (j != expected.size()) {
            throw new AssertionError("recovered only " + j + " of " + expected.size() + " frames in order; read " + actual.size());
        }
    }
}
