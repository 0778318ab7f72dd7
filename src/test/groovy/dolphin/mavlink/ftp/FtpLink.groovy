package dolphin.mavlink.ftp

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_file_transfer_protocol
import dolphin.core.ManualClock
import dolphin.mavlink.LinkRequests
import dolphin.mavlink.RoundTrip

/** Both ends of an FTP link with no socket: the client's channel, whose requests reach a {@link FakeFtpServer}, and back. */
class FtpLink implements FtpChannel {

    final RoundTrip roundTrip = new RoundTrip()
    final FakeFtpServer server
    final FtpClient client
    int sent
    /** Our radio's free buffer in percent; -1: no radio. */
    int radioBufferFree = -1
    FtpPacing pacing = FtpPacing.NETWORK
    /** The requests in flight on the link, which a spec may share between two links' clients (one radio). */
    LinkRequests linkRequests = new LinkRequests()

    FtpLink(ManualClock clock, Closure<FtpClient> client) {
        this.server = new FakeFtpServer(clock, { msg_file_transfer_protocol m -> this.client.handle(m) })
        this.client = client(this)
    }

    @Override
    void send(MAVLinkMessage message) {
        sent++
        server.receive(message as msg_file_transfer_protocol)
    }

    @Override
    int system() { 2 }

    @Override
    int component() { 1 }

    @Override
    int groundSystem() { FakeFtpServer.RECEIVER_SYSTEM }

    @Override
    RoundTrip roundTrip() { roundTrip }

    @Override
    int radioBufferFree() { radioBufferFree }

    @Override
    FtpPacing pacing() { pacing }

    @Override
    LinkRequests linkRequests() { linkRequests }
}
