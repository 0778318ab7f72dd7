package dolphin.sim;

import dolphin.mavlink.ftp.FileCrc32;
import java.io.ByteArrayOutputStream;
import java.util.Arrays;
import java.util.function.Consumer;

/**
 * One MAVLink FTP session of a simulated vehicle, as GCS_FTP::Session handles its requests: at most
 * one file open, for reading or writing; the session id, system and component are the client's.
 * Bursts are sent whole at once (ArduPilot paces them on a serial link; the simulated links have no
 * bandwidth to spare).
 */
final class SimFtpSession {

    /** An open file with no reply for this long may be replaced by a new OpenFileRO (FTP_SESSION_TIMEOUT). */
    static final long STALE_NANOS = 3_000_000_000L;
    /** BurstReadFile's most replies to one request (its transfer_size). */
    static final int BURST_LIMIT = 2000;
    /** AP_Filesystem::crc32 reads a file 64 bytes at a time. */
    private static final int CRC_CHUNK = 64;

    private final MissionFiles files;
    /** Whether a client took the session: its id, system and component are set. */
    private boolean claimed;
    private int id;
    private int sysid;
    private int compid;
    private int fd = -1;
    private boolean writing;
    /** Whether a reply went out since the session was last closed (GCS_FTP's last_send_ms != 0). */
    private boolean active;
    private long lastSend;

    SimFtpSession(MissionFiles files) {
        this.files = files;
    }

    /** Whether the request is this session's: its client's system, component and session id. */
    boolean owns(SimFtpPacket request) {
        return claimed && request.sysid() == sysid && request.compid() == compid && request.session() == id;
    }

    boolean ownedBy(int system, int component) {
        return claimed && system == sysid && component == compid;
    }

    /** Closes what the session had open and gives it to the request's client. */
    void claim(SimFtpPacket request) {
        close();
        claimed = true;
        id = request.session();
        sysid = request.sysid();
        compid = request.compid();
    }

    /** How long since the last reply; a session that never sent, or was closed, counts as idle for ever. */
    long idle(long now) {
        return active ? now - lastSend : Long.MAX_VALUE;
    }

    /** Closes the open file (loading one written): 0, or -errno. */
    int close() {
        int result = 0;
        if (fd != -1) {
            result = files.close(fd);
            fd = -1;
        }
        active = false;
        return result;
    }

    /** Closes the session once it sent nothing for more than {@code nanos} (GCS_FTP's kill of dead sessions). */
    void closeIfIdle(long now, long nanos) {
        if (active && now - lastSend > nanos) {
            close();
        }
    }

    /** Sends the reply and notes the time; a reply to TerminateSession makes the session idle. */
    void push(SimFtpPacket reply, Consumer<SimFtpPacket> link, long now) {
        link.accept(reply);
        active = reply.reqOpcode() != SimFtpPacket.TERMINATE_SESSION;
        lastSend = now;
    }

    /**
     * Answers one request (GCS_FTP::Session::handle_request); the reply to remember, which the
     * caller sends unless {@code sent} says it went out already (a burst) or nothing is to be sent.
     */
    SimFtpOutcome handle(SimFtpPacket request, Consumer<SimFtpPacket> link, long now) {
        SimFtpPacket reply = request.reply();
        if (request.size() > SimFtpPacket.DATA_BYTES) {
            return new SimFtpOutcome(reply.nak(SimFtpPacket.INVALID_DATA_SIZE), false);
        }
        return switch (request.opcode()) {
            case SimFtpPacket.NONE -> new SimFtpOutcome(reply.ack(0, new byte[0], 0), false);
            case SimFtpPacket.TERMINATE_SESSION -> {
                int result = close();
                yield new SimFtpOutcome(result < 0 ? reply.nak(SimFtpPacket.FAIL_ERRNO, -result) : reply.ack(0, new byte[0], 0), false);
            }
            case SimFtpPacket.OPEN_FILE_RO -> new SimFtpOutcome(openRead(request, reply, now), false);
            case SimFtpPacket.READ_FILE -> new SimFtpOutcome(read(request, reply, now), false);
            case SimFtpPacket.BURST_READ_FILE -> burst(request, reply, link, now);
            case SimFtpPacket.CREATE_FILE, SimFtpPacket.OPEN_FILE_WO -> new SimFtpOutcome(openWrite(request, reply, now), false);
            case SimFtpPacket.WRITE_FILE -> new SimFtpOutcome(write(request, reply, now), false);
            case SimFtpPacket.CALC_FILE_CRC32 -> new SimFtpOutcome(crc32(request, reply, now), false);
            // eaten: a client's ACK or NAK is not a request
            case SimFtpPacket.ACK, SimFtpPacket.NAK -> new SimFtpOutcome(reply, true);
            // paths outside @MISSION: the simulated vehicle has no other files or directories
            case SimFtpPacket.LIST_DIRECTORY, SimFtpPacket.REMOVE_FILE, SimFtpPacket.CREATE_DIRECTORY,
                    SimFtpPacket.REMOVE_DIRECTORY, SimFtpPacket.RENAME ->
                    new SimFtpOutcome(reply.nak(request.nameLengthValid() ? SimFtpPacket.FILE_NOT_FOUND : SimFtpPacket.INVALID_DATA_SIZE),
                            false);
            default -> new SimFtpOutcome(reply.nak(SimFtpPacket.FAIL), false);
        };
    }

    /** The reply to remember, and whether it was sent already (or is not to be sent). */
    record SimFtpOutcome(SimFtpPacket reply, boolean sent) {
    }

    private SimFtpPacket openRead(SimFtpPacket request, SimFtpPacket reply, long now) {
        if (fd != -1 && now - lastSend > STALE_NANOS) {
            close(); // the client gave up on its open: ArduPilot closes the file
        }
        if (fd != -1) {
            return reply.nak(SimFtpPacket.FAIL);
        }
        if (!request.nameLengthValid()) {
            return reply.nak(SimFtpPacket.INVALID_DATA_SIZE);
        }
        int opened = files.open(request.path(), true, now);
        if (opened < 0) {
            return reply.nak(SimFtpPacket.FAIL_ERRNO, -opened);
        }
        fd = opened;
        writing = false;
        int size = MissionFiles.FILE_SIZE;
        return reply.ack(4, new byte[] {(byte) size, (byte) (size >> 8), (byte) (size >> 16), (byte) (size >> 24)}, 0);
    }

    private SimFtpPacket read(SimFtpPacket request, SimFtpPacket reply, long now) {
        SimFtpPacket refused = readRefusal(reply);
        if (refused != null) {
            return refused;
        }
        byte[] bytes = files.read(fd, request.offset(), Math.min(SimFtpPacket.DATA_BYTES, request.size()), now);
        if (bytes == null) {
            return reply.nak(SimFtpPacket.FAIL_ERRNO, SimFtpPacket.EBADF);
        }
        if (bytes.length == 0) {
            return reply.nak(SimFtpPacket.EOF);
        }
        return reply.ack(bytes.length, bytes, request.offset());
    }

    /**
     * Replies of up to {@code size} bytes (239 when 0) from the offset on, each an ACK with the next
     * seq; the one short of {@code size} has burst_complete, and the read after it, at the end, is
     * the NAK EOF that ends every burst (ArduPilot keeps reading after a short read).
     */
    private SimFtpOutcome burst(SimFtpPacket request, SimFtpPacket reply, Consumer<SimFtpPacket> link, long now) {
        SimFtpPacket refused = readRefusal(reply);
        if (refused != null) {
            return new SimFtpOutcome(refused, false);
        }
        int most = request.size() == 0 ? SimFtpPacket.DATA_BYTES : request.size();
        SimFtpPacket next = reply;
        long at = request.offset();
        for (int i = 0; i < BURST_LIMIT; i++) {
            byte[] bytes = files.read(fd, at, most, now);
            if (bytes == null) {
                return new SimFtpOutcome(next.cleared().nak(SimFtpPacket.FAIL_ERRNO, SimFtpPacket.EBADF), false);
            }
            if (bytes.length == 0) {
                return new SimFtpOutcome(next.cleared().nak(SimFtpPacket.EOF), false);
            }
            next = next.withBurstComplete(bytes.length < most || i == BURST_LIMIT - 1).ack(bytes.length, bytes, at);
            push(next, link, now);
            at += bytes.length;
            // the NAK after a short read is at the end of the file
            next = (bytes.length < most ? next.withOffset(at) : next).withSeq(next.seq() + 1);
        }
        return new SimFtpOutcome(next, true);
    }

    private SimFtpPacket readRefusal(SimFtpPacket reply) {
        if (fd == -1) {
            return reply.nak(SimFtpPacket.FILE_NOT_FOUND);
        }
        return writing ? reply.nak(SimFtpPacket.FAIL) : null;
    }

    /** The CRC32 of a whole file, read as OpenFileRO would (AP_Filesystem::crc32), in a file slot of its own. */
    private SimFtpPacket crc32(SimFtpPacket request, SimFtpPacket reply, long now) {
        if (!request.nameLengthValid()) {
            return reply.nak(SimFtpPacket.INVALID_DATA_SIZE);
        }
        if (MissionFiles.typeOf(request.path()) == null) {
            return reply.nak(SimFtpPacket.FILE_NOT_FOUND);
        }
        int slot = files.open(request.path(), true, now);
        if (slot < 0) {
            return reply.nak(SimFtpPacket.FAIL_ERRNO, -slot);
        }
        ByteArrayOutputStream whole = new ByteArrayOutputStream();
        for (byte[] chunk = files.read(slot, 0, CRC_CHUNK, now); chunk.length > 0;
                chunk = files.read(slot, whole.size(), CRC_CHUNK, now)) {
            whole.writeBytes(chunk);
        }
        files.close(slot);
        long crc = FileCrc32.of(whole.toByteArray());
        return reply.ack(4, new byte[] {(byte) crc, (byte) (crc >> 8), (byte) (crc >> 16), (byte) (crc >> 24)}, 0);
    }

    private SimFtpPacket openWrite(SimFtpPacket request, SimFtpPacket reply, long now) {
        if (fd != -1) {
            return reply.nak(SimFtpPacket.FAIL);
        }
        if (!request.nameLengthValid()) {
            return reply.nak(SimFtpPacket.INVALID_DATA_SIZE);
        }
        int opened = files.open(request.path(), false, now);
        if (opened < 0) {
            return reply.nak(SimFtpPacket.FAIL_ERRNO, -opened);
        }
        fd = opened;
        writing = true;
        return reply.ack(0, new byte[0], 0);
    }

    private SimFtpPacket write(SimFtpPacket request, SimFtpPacket reply, long now) {
        if (fd == -1) {
            return reply.nak(SimFtpPacket.FILE_NOT_FOUND);
        }
        if (!writing) {
            return reply.nak(SimFtpPacket.FAIL);
        }
        byte[] bytes = Arrays.copyOf(request.data(), request.size());
        int result = files.write(fd, request.offset(), bytes, now);
        if (result < 0) {
            return reply.nak(SimFtpPacket.FAIL_ERRNO, -result);
        }
        return reply.ack(0, new byte[0], request.offset());
    }
}
