package dolphin.mavlink;

import java.io.BufferedOutputStream;
import java.io.Closeable;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;

/**
 * A telemetry log: every frame in and out as an 8-byte big-endian Unix timestamp in microseconds
 * followed by the raw frame, the format pymavlink, MAVProxy and Mission Planner read. Each record
 * goes to the buffer in one write, so the file only ever holds whole records: a run stopped by a
 * signal leaves a log that ends at a record's end.
 */
public final class Tlog implements Closeable {

    private final OutputStream out;

    public Tlog(Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        out = new BufferedOutputStream(Files.newOutputStream(file));
    }

    public synchronized void write(byte[] frame) throws IOException {
        Instant now = Instant.now();
        out.write(ByteBuffer.allocate(Long.BYTES + frame.length)
                .putLong(now.getEpochSecond() * 1_000_000L + now.getNano() / 1000).put(frame).array());
    }

    @Override
    public synchronized void close() throws IOException {
        out.close();
    }
}
