package dolphin.mavlink.ftp;

import dolphin.mavlink.LinkRequests;
import dolphin.mavlink.LinkTimeouts;
import dolphin.mavlink.ProtocolTimers;
import dolphin.mavlink.RoundTrip;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;

/**
 * One session with the vehicle's FTP server, on the protocol's thread: its requests numbered, at
 * most the window of its link's {@link FtpPacing} outstanding (looked at for each request: a radio
 * may be heard after the transfer began), fewer while our radio's buffer fills; each sent again on
 * its own timeout (the link's RTO, backed off per timeout in a row, twice at most), and matched
 * with their replies by session, req_opcode and seq (a reply's seq is its request's plus one); a
 * session that makes no progress for the give-up time fails. A request sent again keeps its seq, so
 * ArduPilot repeats its remembered reply instead of doing it twice. Clean round trips (a reply to a
 * request sent once) feed the link's {@link dolphin.mavlink.RoundTrip}.
 */
final class FtpSession {

    /** A burst answers with up to 2000 packets and an EOF NAK, numbered on from its seq. */
    static final int BURST_REPLIES = 2001;

    /** The operation the session serves; its answers, on the protocol's thread. */
    interface Owner {

        /** The reply (ACK or NAK) to one of its requests; for a burst, its first packet. */
        void answered(FtpPayload request, FtpPayload reply);

        /** A reply of this session that answers no outstanding request: a burst's further packets, a duplicate. */
        void unmatched(FtpPayload reply);

        void failed(FtpException e);
    }

    private static final class OutstandingRequest {
        final FtpPayload request;
        int sends;
        long sentAt;
        int seqAfterSend;       // the session's next seq when it was last sent: later requests have it or more

        OutstandingRequest(FtpPayload request) {
            this.request = request;
        }
    }

    private final FtpChannel channel;
    private final ProtocolTimers timers;
    private final LinkTimeouts timeouts;
    private final int id;
    private final String path;
    private final Runnable onEnd;
    private final LinkRequests onTheLink;
    private final BooleanSupplier heard;
    private final List<OutstandingRequest> pending = new ArrayList<>();
    private Owner owner;
    private int nextSeq;
    private long lastProgress;
    private int timeoutsInARow;
    private int resends;
    private boolean ended;

    /**
     * @param heard whether the vehicle ever answered over FTP, this session or an earlier one
     * @param onEnd runs once the session has ended
     */
    FtpSession(FtpChannel channel, ProtocolTimers timers, LinkTimeouts timeouts, int id, String path,
               BooleanSupplier heard, Runnable onEnd) {
        this.channel = channel;
        this.timers = timers;
        this.timeouts = timeouts;
        this.id = id;
        this.path = path;
        this.onEnd = onEnd;
        this.heard = heard;
        this.onTheLink = channel.linkRequests();
        this.lastProgress = timers.nanoTime();
    }

    void serve(Owner o) {
        owner = o;
    }

    int id() {
        return id;
    }

    String path() {
        return path;
    }

    LinkTimeouts timeouts() {
        return timeouts;
    }

    RoundTrip roundTrip() {
        return channel.roundTrip();
    }

    /** The file bytes per request or reply on this link now, 1 to 239 (fewer once a radio is heard on it). */
    int dataBytes() {
        return channel.pacing().dataBytes();
    }

    ProtocolTimers timers() {
        return timers;
    }

    int resends() {
        return resends;
    }

    boolean ended() {
        return ended;
    }

    /** Requests that may still be sent now. */
    int free() {
        if (ended) {
            return 0;
        }
        FtpPacing pacing = channel.pacing();
        int own = window(pacing.window(), channel.radioBufferFree()) - pending.size();
        int onLink = pacing.linkWindow() == Integer.MAX_VALUE ? own : pacing.linkWindow() - onTheLink.inFlight();
        // each transfer may always have one in flight, or it could wait for ever on the others
        return Math.max(Math.min(own, onLink), pending.isEmpty() ? 1 : 0);
    }

    /**
     * Requests outstanding at most, given how much of our radio's buffer is free: the whole
     * {@code window} from half free up (or without a radio), two from a fifth, one below: the
     * thresholds at which ArduPilot slows its own streams by its radio's report.
     */
    static int window(int window, int radioBufferFree) {
        return radioBufferFree < 0 || radioBufferFree >= 50 ? window : Math.min(window, radioBufferFree >= 20 ? 2 : 1);
    }

    /** Sends a request naming the session's file (OpenFileRO, CreateFile). */
    FtpPayload sendPath(int opcode) {
        byte[] name = path.getBytes(StandardCharsets.UTF_8);
        return send(opcode, name.length, 0, name);
    }

    /** Sends a request; it is sent again on its timeout until answered. */
    FtpPayload send(int opcode, int size, long offset, byte[] data) {
        FtpPayload request = FtpPayload.request(nextSeq, id, opcode, size, offset, data);
        // the replies to a burst are numbered on from its seq: a later request must not look like
        // a repeat of the one ArduPilot answered last, or it gets that reply again
        nextSeq = (nextSeq + (opcode == FtpPayload.BURST_READ_FILE ? BURST_REPLIES + 1 : 1)) & 0xffff;
        OutstandingRequest p = new OutstandingRequest(request);
        pending.add(p);
        onTheLink.add(1);
        transmit(p);
        return request;
    }

    private void transmit(OutstandingRequest p) {
        p.sends++;
        p.sentAt = timers.nanoTime();
        p.seqAfterSend = nextSeq;
        int sends = p.sends;
        channel.send(p.request.toMessage(channel.system(), channel.component()));
        Duration timeout = timeouts.timeout(channel.roundTrip(), timeoutsInARow);
        Duration shortest = channel.pacing().shortestTimeout();
        timers.schedule(timeout.compareTo(shortest) < 0 ? shortest : timeout, () -> {
            if (!ended && p.sends == sends && pending.contains(p)) {
                timedOut(p);
            }
        });
    }

    private void timedOut(OutstandingRequest p) {
        timeoutsInARow++;
        if (timers.nanoTime() - lastProgress >= timeouts.giveUp().toNanos()) {
            fail(FtpException.noAnswer(path, p.request, p.sends, timeouts.giveUp(), heard.getAsBoolean()));
            return;
        }
        resends++;
        transmit(p);
    }

    /** Something new came from the vehicle: timeouts start over. */
    void progressed() {
        lastProgress = timers.nanoTime();
        timeoutsInARow = 0;
    }

    /** A reply whose session is this one. */
    void handle(FtpPayload reply) {
        if (ended || owner == null) {
            return;
        }
        OutstandingRequest p = match(reply);
        if (p == null) {
            owner.unmatched(reply);
            return;
        }
        pending.remove(p);
        onTheLink.add(-1);
        if (p.sends == 1 && ((reply.seq() - p.request.seq()) & 0xffff) == 1) {
            channel.roundTrip().sample(timers.nanoTime() - p.sentAt);
        }
        progressed();
        owner.answered(p.request, reply);
    }

    /**
     * Sends the outstanding request of {@code opcode} again now, unless it was sent again since the
     * request {@code later} (whose answer shows it lost: ArduPilot serves requests in order). Whether
     * it was sent.
     */
    boolean resendLostBefore(int opcode, FtpPayload later) {
        for (OutstandingRequest p : pending) {
            if (p.request.opcode() == opcode) {
                if (((later.seq() - p.seqAfterSend) & 0x8000) != 0) {
                    return false;       // sent again after the later request: its answer may still come
                }
                resends++;
                transmit(p);
                return true;
            }
        }
        return false;
    }

    /**
     * Stops waiting for the outstanding requests of one opcode: they are not sent again, and their
     * replies, should they come, answer nothing.
     */
    void withdraw(int opcode) {
        int before = pending.size();
        pending.removeIf(p -> p.request.opcode() == opcode);
        onTheLink.add(pending.size() - before);
    }

    private OutstandingRequest match(FtpPayload reply) {
        for (OutstandingRequest p : pending) {
            FtpPayload q = p.request;
            if (reply.reqOpcode() != q.opcode()) {
                continue;
            }
            int d = (reply.seq() - q.seq()) & 0xffff;
            if (q.opcode() == FtpPayload.BURST_READ_FILE ? d >= 1 && d <= BURST_REPLIES
                    : d == 1 && (reply.opcode() != FtpPayload.ACK || !carriesOffset(q) || reply.offset() == q.offset())) {
                return p;
            }
        }
        return null;
    }

    private static boolean carriesOffset(FtpPayload request) {
        return request.opcode() == FtpPayload.READ_FILE || request.opcode() == FtpPayload.WRITE_FILE;
    }

    /** Ends the session without closing anything (the file was closed by an answered TerminateSession). */
    void finish() {
        if (!ended) {
            ended = true;
            onTheLink.add(-pending.size());
            pending.clear();
            onEnd.run();
        }
    }

    /** Ends the session, closing its file: one TerminateSession, not waited for (ArduPilot closes idle sessions itself). */
    void close() {
        if (!ended) {
            channel.send(FtpPayload.request(nextSeq, id, FtpPayload.TERMINATE_SESSION, 0, 0, null)
                    .toMessage(channel.system(), channel.component()));
            finish();
        }
    }

    /** Closes the session and tells its owner why. */
    void fail(FtpException e) {
        if (!ended) {
            close();
            owner.failed(e);
        }
    }
}
