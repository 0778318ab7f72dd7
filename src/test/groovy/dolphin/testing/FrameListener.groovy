package dolphin.testing

import dolphin.mavlink.codec.Frame
import dolphin.mavlink.codec.FrameReader

/**
 * The receiving half of a test peer on a UDP socket: a thread that reads datagrams, splits them into
 * MAVLink frames with our FrameReader, and hands each frame and its sender's address to a closure.
 * Closing it closes the socket, which also ends a receive under way.
 */
class FrameListener implements AutoCloseable {

    private final DatagramSocket socket
    private final Thread thread

    FrameListener(DatagramSocket socket, String name, Closure onFrame) {
        this.socket = socket
        thread = Thread.start(name) {
            def reader = new FrameReader()
            byte[] buf = new byte[65535]
            while (true) { // until close() closes the socket
                def p = new DatagramPacket(buf, buf.length)
                try {
                    socket.receive(p)
                } catch (IOException closed) {
                    return
                }
                SocketAddress from = p.socketAddress
                reader.feed(p.data, 0, p.length) { Frame f -> onFrame(f, from) }
                reader.endOfPacket { Frame f -> onFrame(f, from) }
            }
        }
    }

    @Override
    void close() {
        socket.close()
        thread.join(2000)
    }
}
