package dolphin.mavlink.ftp;

import com.MAVLink.common.msg_file_transfer_protocol;
import dolphin.mavlink.LinkTimeouts;
import dolphin.mavlink.ProtocolTimers;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.function.ToIntFunction;

/**
 * A MAVLink FTP client for one vehicle (docs/mavlink.md, "Mission transfers over FTP"): reads and
 * writes whole files, each over a session of its own, on the protocol's thread
 * ({@link ProtocolTimers}); the vehicle's FILE_TRANSFER_PROTOCOL messages come in through
 * {@link #handle}. A failed transfer completes its future with an {@link FtpException}.
 */
public final class FtpClient {

    private final FtpChannel channel;
    private final ProtocolTimers timers;
    private final Map<Integer, FtpSession> sessions = new HashMap<>();
    private int lastSession;
    private boolean heard;

    public FtpClient(FtpChannel channel, ProtocolTimers timers) {
        this.channel = channel;
        this.timers = timers;
    }

    /**
     * Reads a whole file; from any thread.
     *
     * @param length the file's whole length from its first bytes, or -1 while they do not tell
     *               (MissionFtpFile's length for @MISSION files, whose reported size is a fake 1 MiB);
     *               null reads to the end of the file
     */
    public CompletableFuture<FtpFile> read(String path, ToIntFunction<byte[]> length, LinkTimeouts timeouts,
                                           FtpProgress progress) {
        CompletableFuture<FtpFile> result = new CompletableFuture<>();
        timers.execute(() -> new FtpRead(open(path, timeouts), length, orNone(progress)).start().whenComplete((f, e) -> {
            if (e == null) {
                result.complete(f);
            } else {
                result.completeExceptionally(e);
            }
        }));
        return result;
    }

    /** Writes a whole file, replacing what the vehicle had; from any thread. */
    public CompletableFuture<FtpFile> write(String path, byte[] bytes, LinkTimeouts timeouts, FtpProgress progress) {
        CompletableFuture<FtpFile> result = new CompletableFuture<>();
        timers.execute(() -> new FtpWrite(open(path, timeouts), bytes, orNone(progress), () -> { }).start().whenComplete((f, e) -> {
            if (e == null) {
                result.complete(f);
            } else {
                result.completeExceptionally(e);
            }
        }));
        return result;
    }

    /**
     * Writes a whole file, replacing what the vehicle had, and has the vehicle compute the CRC32 of
     * what it holds once the file is closed ({@link FtpCheckedWrite}): a check of the write that
     * costs no round trip of its own; from any thread.
     */
    public CompletableFuture<CheckedFile> writeChecked(String path, byte[] bytes, LinkTimeouts timeouts, FtpProgress progress) {
        CompletableFuture<CheckedFile> result = new CompletableFuture<>();
        timers.execute(() -> new FtpCheckedWrite(open(path, timeouts), bytes, orNone(progress), () -> open(path, timeouts))
                .start().whenComplete((f, e) -> {
                    if (e == null) {
                        result.complete(f);
                    } else {
                        result.completeExceptionally(e);
                    }
                }));
        return result;
    }

    /**
     * The vehicle's CRC32 of a whole file ({@link FileCrc32}), which it reads itself: a read-back
     * that costs one round trip; from any thread.
     */
    public CompletableFuture<Long> crc32(String path, LinkTimeouts timeouts) {
        CompletableFuture<Long> result = new CompletableFuture<>();
        timers.execute(() -> new FtpChecksum(open(path, timeouts)).start().whenComplete((crc, e) -> {
            if (e == null) {
                result.complete(crc);
            } else {
                result.completeExceptionally(e);
            }
        }));
        return result;
    }

    /** Whether the vehicle ever answered over FTP: it has MAVLink FTP, whatever else it said. */
    public boolean heard() {
        return heard;
    }

    /**
     * Gives up every transfer under way, closing its file (a TerminateSession each): the vehicle
     * is not waited for any longer. Their futures fail with {@code why}; on the protocol's thread.
     */
    public void abandon(String why) {
        new ArrayList<>(sessions.values()).forEach(s -> s.fail(FtpException.abandoned(s.path(), why, heard)));
    }

    private static FtpProgress orNone(FtpProgress p) {
        return p == null ? FtpProgress.NONE : p;
    }

    /** A new session: ids go round 1 to 255, so a reply to an earlier transfer never matches a later one. */
    private FtpSession open(String path, LinkTimeouts timeouts) {
        do {
            lastSession = lastSession % 255 + 1;
        } while (sessions.containsKey(lastSession));
        int id = lastSession;
        FtpSession s = new FtpSession(channel, timers, timeouts, id, path, () -> heard, () -> sessions.remove(id));
        sessions.put(id, s);
        return s;
    }

    /** A FILE_TRANSFER_PROTOCOL message from the vehicle, on the protocol's thread. */
    public void handle(msg_file_transfer_protocol message) {
        if (message.target_system != 0 && message.target_system != channel.groundSystem()) {
            return;
        }
        FtpPayload reply = FtpPayload.decode(message);
        if (reply.opcode() != FtpPayload.ACK && reply.opcode() != FtpPayload.NAK) {
            return;
        }
        heard = true;
        FtpSession s = sessions.get(reply.session());
        if (s != null) {
            s.handle(reply);
        }
    }
}
