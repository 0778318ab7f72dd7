package dolphin.mavlink

import dolphin.mavlink.link.Link
import dolphin.mavlink.link.LinkUrl

/**
 * A link with no socket and no reader thread: a spec hands its bytes to the communications as the
 * reader thread would ({@link #from}), and reads every frame they sent on it ({@link #sent}).
 */
class FakeLink extends Link {

    static final SocketAddress PEER = new InetSocketAddress('127.0.0.1', 14550)

    final List<byte[]> sent = []

    FakeLink(String url, int index) {
        super(LinkUrl.parse(url), index)
    }

    /** Bytes as the link's reader hands them over: a serial port's chunk, or one whole datagram. */
    Link.Received from(byte[] bytes) {
        new Link.Received(this, PEER, bytes, datagrams())
    }

    @Override
    boolean datagrams() { url().kind() != LinkUrl.Transport.SERIAL }

    @Override
    void send(byte[] frame, SocketAddress peer) { sent << frame }

    @Override
    SocketAddress fixedPeer() { null }

    @Override
    protected Link.Received receive() { null }

    @Override
    protected void closeTransport() {}
}
