package dolphin.mavlink;

import java.io.BufferedOutputStream;
import java.io.Closeable;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;

/**
 * A telemetry log: every frame in and out as an 8-byte big-endian Unix timestamp in microseconds
 * followed by the raw frame, the format pymavlink, MAVProxy and Mission Planner read.
 */
public final class Tlog implements Closeable {

    private final DataOutputStream out;

    public Tlog(Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        out = new DataOutputStream(new BufferedOutputStream(Files.newOutputStream(file)));
    }

    public synchronized void write(byte[] frame) throws IOException {
        Instant now = Instant.now();
        out.writeLong(now.getEpochSecond() * 1_000_000L + now.getNano() / 1000);
        out.write(frame);
    }

    @Override
    public synchronized void close() throws IOException {
        out.close();
    }
}
