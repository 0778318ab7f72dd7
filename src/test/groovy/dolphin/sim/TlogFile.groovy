package dolphin.sim

import dolphin.mavlink.codec.Frame
import dolphin.mavlink.codec.FrameReader

import java.nio.file.Files
import java.nio.file.Path

/**
 * A telemetry log read with our codec: each record an 8-byte big-endian Unix time in microseconds
 * (what dolphin.mavlink.Tlog writes) followed by one raw MAVLink 1 or 2 frame, whose length its
 * header gives. A last record cut short (the recording process was killed) is left out.
 */
class TlogFile {

    static class Record {
        final long micros
        final Frame frame

        Record(long micros, Frame frame) {
            this.micros = micros
            this.frame = frame
        }
    }

    static List<Record> read(Path file) {
        def reader = new FrameReader()
        List<Record> records = []
        new DataInputStream(new BufferedInputStream(Files.newInputStream(file))).withCloseable { input ->
            while (input.available() > 0) {
                Record record
                try {
                    record = next(input, reader, file)
                } catch (EOFException ignored) {
                    break // cut short
                }
                if (record != null) {
                    records << record
                }
            }
        }
        records
    }

    /** The next record; null when its bytes are no frame the reader accepts. */
    private static Record next(DataInputStream input, FrameReader reader, Path file) {
        long micros = input.readLong()
        int stx = input.readUnsignedByte()
        int len = input.readUnsignedByte()
        int rest
        byte[] head
        if (stx == 0xFD) {
            head = new byte[8]
            input.readFully(head)
            boolean signed = (head[0] & 0x01) != 0
            rest = len + 2 + (signed ? 13 : 0)
        } else {
            assert stx == 0xFE: "${file}: no frame after the timestamp ${micros}"
            head = new byte[4]
            input.readFully(head)
            rest = len + 2
        }
        byte[] bytes = new byte[2 + head.length + rest]
        bytes[0] = (byte) stx
        bytes[1] = (byte) len
        System.arraycopy(head, 0, bytes, 2, head.length)
        input.readFully(bytes, 2 + head.length, rest)
        List<Frame> frames = []
        reader.feed(bytes, 0, bytes.length) { frames << it }
        reader.endOfPacket { frames << it }
        frames ? new Record(micros, frames[0]) : null
    }
}
