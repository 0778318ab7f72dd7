package dolphin.mavlink.ftp

import com.MAVLink.common.msg_file_transfer_protocol
import dolphin.core.ManualClock
import java.nio.ByteBuffer
import java.nio.ByteOrder
import java.nio.charset.StandardCharsets
import java.time.Duration

/**
 * ArduPilot's MAVLink FTP server (GCS_FTP.cpp, AP_Filesystem_Mission.cpp) on a manual clock, with
 * no socket: requests go through a queue of 5 (more are dropped), replies echo the session with
 * seq + 1, a request repeating the last one answered gets that reply again, bursts stream 239-byte
 * packets ending with a short one (burst_complete) and an EOF NAK. Files are kept in
 * {@link #files}; @MISSION files report a fake size of 1 MiB, at most four are open at a time,
 * and they are parsed when closed after a write: magic, an item count matching the length, no
 * all-zero item, then {@link #refuseList}.
 * The link may lose, duplicate and reorder packets, from a seed, or by rules
 * ({@link #dropRequest}, {@link #dropReply}); {@link #silent} answers nothing (a vehicle without FTP).
 */
class FakeFtpServer {

    static final int MISSION_MAGIC = 0x763d
    static final int ITEM_BYTES = 38
    /** AP_Filesystem_Mission's open files (max_open_file): an open beyond them is refused, FailErrno ENFILE. */
    static final int MISSION_FILES = 4

    final ManualClock clock
    /** Hands a reply to the client. */
    final Closure toClient
    final Map<String, byte[]> files = [:]
    /** Whether a parsed @MISSION list is refused when converted (a bad DO_JUMP, say): path, bytes. */
    Closure<Boolean> refuseList = { String path, byte[] bytes -> false }
    /** What the vehicle keeps of a file written and accepted (ArduPilot stores a list its own way): path, bytes. */
    Closure<byte[]> keep = { String path, byte[] bytes -> bytes }
    /** Whether CalcFileCRC32 is refused, as by a vehicle without it. */
    boolean refuseCrc
    Duration latency = Duration.ofMillis(20)
    Duration serviceTime = Duration.ofMillis(1)
    /** Extra random delay of each packet, which reorders them. */
    Duration jitter = Duration.ZERO
    double lossUp
    double lossDown
    double duplicate
    Random random = new Random(1)
    boolean silent
    /** Whether a request is lost on its way (the request, how many of its kind came before). */
    Closure<Boolean> dropRequest = { FtpPayload p, int n -> false }
    /** Whether a reply is lost on its way (the reply, how many of its kind were sent before). */
    Closure<Boolean> dropReply = { FtpPayload p, int n -> false }
    /** What crossed the link: "0.020 > WriteFile seq 3 ...", "0.041 < ACK to WriteFile ..."; lost ones say so. */
    final List<String> log = []
    /** Requests that arrived, per opcode name. */
    final Map<String, Integer> requests = [:].withDefault { 0 }
    /** Requests dropped because the queue of 5 was full. */
    int dropped
    int mostQueued

    private final Map<String, Integer> sentReplies = [:].withDefault { 0 }
    private final Map<String, Integer> sentRequests = [:].withDefault { 0 }
    private final List<FtpPayload> queue = []
    private final Map<Integer, Map> sessions = [:]
    private FtpPayload last

    FakeFtpServer(ManualClock clock, Closure toClient) {
        this.clock = clock
        this.toClient = toClient
    }

    /** A request as the client sends it. */
    void receive(msg_file_transfer_protocol m) {
        FtpPayload p = FtpPayload.decode(m)
        String name = FtpPayload.opcodeName(p.opcode())
        int n = sentRequests[name]++
        boolean lost = dropRequest(p, n) || random.nextDouble() < lossUp
        log << "${t()} > ${p}${lost ? ' (lost)' : ''}".toString()
        if (lost) {
            return
        }
        clock.schedule(delay()) { arrive(p) }
    }

    private Duration delay() {
        jitter.isZero() ? latency : latency + Duration.ofNanos((long) (random.nextDouble() * jitter.toNanos()))
    }

    private String t() { String.format(Locale.ROOT, '%.3f', clock.seconds()) }

    private void arrive(FtpPayload p) {
        if (silent) {
            return
        }
        requests[FtpPayload.opcodeName(p.opcode())]++
        if (queue.size() >= 5) {
            dropped++
            return
        }
        queue << p
        mostQueued = Math.max(mostQueued, queue.size())
        if (queue.size() == 1) {
            clock.schedule(serviceTime) { work() }
        }
    }

    private void work() {
        FtpPayload p = queue.remove(0)
        serve(p)
        if (!queue.isEmpty()) {
            clock.schedule(serviceTime) { work() }
        }
    }

    private void serve(FtpPayload r) {
        if (r.opcode() == FtpPayload.RESET_SESSIONS) {
            new ArrayList<>(sessions.keySet()).each { close(it) }
            reply(ack(r, 0, 0, null))
            return
        }
        Map s = sessions[r.session()]
        if (s == null) {
            if (sessions.size() >= 5) {
                reply(nak(r, FtpErrors.NO_SESSIONS_AVAILABLE))
                return
            }
            s = sessions[r.session()] = [path: null, mode: null, buffer: null]
        }
        if (last != null && last.session() == r.session() && ((r.seq() + 1) & 0xffff) == last.seq()
                && last.error() != FtpErrors.NO_SESSIONS_AVAILABLE) {
            reply(last)
            return
        }
        switch (r.opcode()) {
            case FtpPayload.TERMINATE_SESSION:
                Integer errno = close(r.session())
                reply(errno == null ? ack(r, 0, 0, null) : nak(r, 2, errno))
                break
            case FtpPayload.OPEN_FILE_RO:
                String path = name(r)
                if (s.path != null) {
                    reply(nak(r, FtpErrors.FAIL))
                } else if (noMissionFile(path)) {
                    reply(nak(r, FtpErrors.FAIL_ERRNO, FtpErrors.ENFILE))
                } else if (!files.containsKey(path)) {
                    reply(nak(r, 10))
                } else {
                    s.path = path
                    s.mode = 'read'
                    int size = mission(path) ? 1024 * 1024 : files[path].length
                    reply(ack(r, 4, 0, ByteBuffer.allocate(4).order(ByteOrder.LITTLE_ENDIAN).putInt(size).array()))
                }
                break
            case FtpPayload.CREATE_FILE:
                if (s.path != null) {
                    reply(nak(r, FtpErrors.FAIL))
                } else if (noMissionFile(name(r))) {
                    reply(nak(r, FtpErrors.FAIL_ERRNO, FtpErrors.ENFILE))
                } else {
                    s.path = name(r)
                    s.mode = 'write'
                    s.buffer = new ByteArrayOutputStream()
                    s.bytes = new byte[0]
                    reply(ack(r, 0, 0, null))
                }
                break
            case FtpPayload.WRITE_FILE:
                if (s.path == null) {
                    reply(nak(r, 10))
                } else {
                    write(s, r)
                    reply(ack(r, 0, r.offset(), null))
                }
                break
            case FtpPayload.READ_FILE:
                if (s.path == null || s.mode != 'read') {
                    reply(nak(r, s.path == null ? 10 : FtpErrors.FAIL))
                } else {
                    byte[] f = files[s.path]
                    if (r.offset() >= f.length) {
                        reply(nak(r, FtpErrors.EOF))
                    } else {
                        byte[] d = Arrays.copyOfRange(f, (int) r.offset(), (int) Math.min(f.length, r.offset() + r.size()))
                        reply(ack(r, d.length, r.offset(), d))
                    }
                }
                break
            case FtpPayload.CALC_FILE_CRC32:
                // nothing opened in the session: the file is read whole (AP_Filesystem::crc32)
                sessions.remove(r.session())
                String crcPath = name(r)
                if (refuseCrc) {
                    reply(nak(r, FtpErrors.FAIL))
                } else if (!files.containsKey(crcPath)) {
                    reply(nak(r, 10))
                } else {
                    long crc = FileCrc32.of(files[crcPath])
                    reply(ack(r, 4, 0, ByteBuffer.allocate(4).order(ByteOrder.LITTLE_ENDIAN).putInt((int) crc).array()))
                }
                break
            case FtpPayload.BURST_READ_FILE:
                if (s.path == null || s.mode != 'read') {
                    reply(nak(r, s.path == null ? 10 : FtpErrors.FAIL))
                } else {
                    burst(r, files[s.path])
                }
                break
            default:
                reply(nak(r, FtpErrors.FAIL))
        }
    }

    private void burst(FtpPayload r, byte[] f) {
        int max = r.size() == 0 ? 239 : r.size()
        long offset = r.offset()
        int seq = r.seq() + 1
        for (int i = 0; i < 2000; i++) {
            if (offset >= f.length) {
                reply(new FtpPayload(seq & 0xffff, r.session(), FtpPayload.NAK, 1, r.opcode(), false, 0, [FtpErrors.EOF] as byte[]))
                return
            }
            byte[] d = Arrays.copyOfRange(f, (int) offset, (int) Math.min(f.length, offset + max))
            reply(new FtpPayload(seq & 0xffff, r.session(), FtpPayload.ACK, d.length, r.opcode(), d.length < max, offset, d))
            offset += d.length
            seq++
        }
    }

    private static boolean mission(String path) { path.startsWith('@MISSION/') }

    /** Whether every @MISSION file is open already, so an @MISSION path cannot be opened. */
    private boolean noMissionFile(String path) {
        mission(path) && sessions.values().count { it.path != null && mission(it.path) } >= MISSION_FILES
    }

    private static String name(FtpPayload r) { new String(r.data(), 0, r.size(), StandardCharsets.UTF_8) }

    /** As AP_Filesystem_Mission: a header at offset 0 sizes the whole buffer (zero-filled). */
    private static void write(Map s, FtpPayload r) {
        byte[] b = s.bytes
        int end = (int) r.offset() + r.size()
        if (r.offset() == 0 && r.size() >= 10 && mission(s.path)) {
            int count = ByteBuffer.wrap(r.data()).order(ByteOrder.LITTLE_ENDIAN).getShort(8) & 0xffff
            end = Math.max(end, 10 + count * ITEM_BYTES)
        }
        if (end > b.length) {
            b = Arrays.copyOf(b, end)
        }
        System.arraycopy(r.data(), 0, b, (int) r.offset(), r.size())
        s.bytes = b
    }

    /** Closes a session's file: null, or the errno of a refused @MISSION file. */
    private Integer close(int session) {
        Map s = sessions.remove(session)
        if (s?.mode != 'write') {
            return null
        }
        byte[] b = s.bytes
        if (mission(s.path) && !acceptable(s.path, b)) {
            return 22
        }
        files[s.path] = keep(s.path, b)
        null
    }

    private boolean acceptable(String path, byte[] b) {
        if (b.length < 10) {
            return false
        }
        ByteBuffer h = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN)
        int count = h.getShort(8) & 0xffff
        if ((h.getShort(0) & 0xffff) != MISSION_MAGIC || (b.length - 10).intdiv(ITEM_BYTES) != count) {
            return false
        }
        for (int i = 0; i < count; i++) {
            int from = 10 + i * ITEM_BYTES
            if ((from..<from + ITEM_BYTES).every { b[it] == 0 }) {
                return false
            }
        }
        !refuseList(path, b)
    }

    private static FtpPayload ack(FtpPayload r, int size, long offset, byte[] data) {
        new FtpPayload((r.seq() + 1) & 0xffff, r.session(), FtpPayload.ACK, size, r.opcode(), false, offset, data)
    }

    private static FtpPayload nak(FtpPayload r, int error, Integer errno = null) {
        byte[] d = errno == null ? [error] as byte[] : [error, errno] as byte[]
        new FtpPayload((r.seq() + 1) & 0xffff, r.session(), FtpPayload.NAK, d.length, r.opcode(), false, 0, d)
    }

    private void reply(FtpPayload p) {
        last = p
        String name = FtpPayload.opcodeName(p.reqOpcode())
        int n = sentReplies[name]++
        boolean lost = dropReply(p, n) || random.nextDouble() < lossDown
        log << "${t()} < ${p}${lost ? ' (lost)' : ''}".toString()
        if (lost) {
            return
        }
        int copies = random.nextDouble() < duplicate ? 2 : 1
        copies.times {
            msg_file_transfer_protocol m = p.toMessage(RECEIVER_SYSTEM, 190)
            clock.schedule(delay()) { toClient(m) }
        }
    }

    String toString() { "FakeFtpServer(${files.keySet()}, requests ${requests})" }

    /** Our ground station's system id, the target of every reply. */
    static final int RECEIVER_SYSTEM = 208
}
