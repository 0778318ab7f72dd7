package dolphin.mavlink

import dolphin.mavlink.codec.Frame
import dolphin.mavlink.codec.FrameReader
import dolphin.mavlink.link.Link
import dolphin.mavlink.link.LinkUrl

/**
 * A link with no socket and no reader thread: a spec hands its bytes to the communications as the
 * reader thread would, from the link's own {@link #peer} ({@link #from}, {@link #datagram}), and reads
 * every frame they sent on it ({@link #sent}, {@link #sentFrames}). With
 * {@link MAVLinkCommunications#attach} the bytes go in through {@code receive} at once; with
 * {@link MAVLinkCommunications#attachForSpecs} through {@code received} and {@code runDue}.
 */
class FakeLink extends Link {

    final SocketAddress peer
    final List<byte[]> sent = []

    FakeLink(String url, int index) {
        super(LinkUrl.parse(url), index)
        peer = new InetSocketAddress("10.0.0.${index + 1}", 14550)
    }

    FakeLink(int index, String url) {
        this(url, index)
    }

    /** Bytes as the link's reader hands them over: a serial port's chunk, or one whole datagram. */
    Link.Received from(byte[] bytes) {
        new Link.Received(this, peer, bytes, datagrams())
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
    boolean datagrams() { url().kind() != LinkUrl.Transport.SERIAL }

    @Override
    void send(byte[] frame, SocketAddress to) { sent << frame }

    @Override
    SocketAddress fixedPeer() { null }

    @Override
    protected Link.Received receive() { null }

    @Override
    protected void closeTransport() {}
}
