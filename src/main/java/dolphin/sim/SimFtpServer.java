package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_file_transfer_protocol;
import java.util.function.Consumer;

/**
 * A simulated vehicle's MAVLink FTP server, as ArduPilot's GCS_FTP worker runs it: five sessions
 * keyed by the client's system, component and session id (a new one takes the longest idle
 * session, if idle for 3 s, else NAK NoSessionsAvailable); ResetSessions closes the requester's
 * sessions and ACKs; a request equal (system, component, session, seq) to the one last answered
 * gets that reply again; a session with no reply for 20 s is closed. Each request is answered when
 * it arrives, so ArduPilot's queue of five requests never fills here and none is dropped.
 */
final class SimFtpServer {

    static final int SESSIONS = 5;
    /** A session idle this long is closed (FTP_SESSION_KILL_TIMEOUT). */
    static final long KILL_NANOS = 20_000_000_000L;

    private final SimFtpSession[] sessions = new SimFtpSession[SESSIONS];
    private final Consumer<SimFtpPacket> link;
    /** The last reply set up, sent or not (GCS_FTP's one reply). */
    private SimFtpPacket last;

    SimFtpServer(MissionFiles files, Consumer<MAVLinkMessage> out) {
        for (int i = 0; i < SESSIONS; i++) {
            sessions[i] = new SimFtpSession(files);
        }
        this.link = p -> out.accept(p.toMessage());
    }

    void handle(msg_file_transfer_protocol m, long now) {
        SimFtpPacket request = SimFtpPacket.of(m);
        if (request.opcode() == SimFtpPacket.RESET_SESSIONS) {
            for (SimFtpSession s : sessions) {
                if (s.ownedBy(request.sysid(), request.compid())) {
                    s.close();
                }
            }
            last = request.reply().ack(0, new byte[0], 0);
            link.accept(last);
            return;
        }
        SimFtpSession session = session(request, now);
        if (session == null) {
            return;
        }
        if (last != null && request.sysid() == last.sysid() && request.compid() == last.compid()
                && request.session() == last.session() && ((request.seq() + 1) & 0xffff) == last.seq()
                && last.data()[0] != SimFtpPacket.NO_SESSIONS_AVAILABLE) {
            session.push(last, link, now);
            return;
        }
        SimFtpSession.SimFtpOutcome handled = session.handle(request, link, now);
        last = handled.reply();
        if (!handled.sent()) {
            session.push(last, link, now);
        }
    }

    /** Closes sessions with no reply for 20 s (a file written is loaded then, as ArduPilot's close does). */
    void tick(long now) {
        for (SimFtpSession s : sessions) {
            s.closeIfIdle(now, KILL_NANOS);
        }
    }

    /** The request's session, claimed if new; null when all are busy (the NAK sent). */
    private SimFtpSession session(SimFtpPacket request, long now) {
        for (SimFtpSession s : sessions) {
            if (s.owns(request)) {
                return s;
            }
        }
        SimFtpSession oldest = sessions[0];
        for (SimFtpSession s : sessions) {
            if (s.idle(now) > oldest.idle(now)) {
                oldest = s;
            }
        }
        if (oldest.idle(now) < SimFtpSession.STALE_NANOS) {
            last = request.reply().nak(SimFtpPacket.NO_SESSIONS_AVAILABLE);
            link.accept(last);
            return null;
        }
        oldest.claim(request);
        return oldest;
    }
}
