package dolphin.mavlink

import dolphin.mavlink.codec.Frame
import dolphin.mavlink.codec.FrameReader
import dolphin.mavlink.link.Link
import dolphin.mavlink.link.LinkUrl

/**
 * A link without a socket, for {@link MAVLinkCommunications#attachForSpecs}: a spec hands its bytes
 * to the communications as if from {@link #peer}, and it keeps what is sent on it.
 */
class FakeLink extends Link {

    final SocketAddress peer
    final List<byte[]> sent = []

    FakeLink(int index, String url) {
        super(LinkUrl.parse(url), index)
        peer = new InetSocketAddress("10.0.0.${index + 1}", 14550)
    }

    /** The bytes as one datagram from the vehicle. */
    Link.Received datagram(byte[] bytes) {
        new Link.Received(this, peer, bytes, true)
    }

    /** The frames sent on this link, decoded. */
    List<Frame> sentFrames() {
        def frames = []
        def reader = new FrameReader()
        sent.each { byte[] b -> reader.feed(b, 0, b.length, { frames << it }) }
        frames
    }

    @Override
    boolean datagrams() { true }

    @Override
    void send(byte[] frame, SocketAddress to) { sent << frame }

    @Override
    SocketAddress fixedPeer() { null }

    @Override
    protected Link.Received receive() { throw new UnsupportedOperationException('a fake link is fed by its spec') }

    @Override
    protected void closeTransport() { }
}
