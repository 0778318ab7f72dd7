package dolphin.mavlink.link;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.util.Arrays;

/** udpin (bound to a port; replies go to each sender's address) and udpout (sends to one address). */
final class UdpLink extends Link {

    private final DatagramSocket socket;
    private final SocketAddress remote;
    private final byte[] buffer = new byte[65535];

    UdpLink(LinkUrl url, int index) throws IOException {
        super(url, index);
        if (url.kind() == LinkUrl.Transport.UDPIN) {
            remote = null;
            try {
                socket = new DatagramSocket(new InetSocketAddress(url.host(), url.port()));
            } catch (SocketException e) {
                throw new IOException("cannot listen on " + url + ": " + e.getMessage(), e);
            }
        } else {
            remote = url.address();
            if (((InetSocketAddress) remote).isUnresolved()) {
                throw new IOException("cannot resolve the host of " + url);
            }
            socket = new DatagramSocket();
        }
        socket.setSoTimeout(500);
        socket.setReceiveBufferSize(1 << 20);
    }

    @Override
    public int localPort() {
        return socket.getLocalPort();
    }

    @Override
    public boolean datagrams() {
        return true;
    }

    @Override
    public SocketAddress fixedPeer() {
        return remote;
    }

    @Override
    public void send(byte[] frame, SocketAddress peer) throws IOException {
        SocketAddress to = remote != null ? remote : peer;
        socket.send(new DatagramPacket(frame, frame.length, to));
    }

    @Override
    protected Received receive() throws IOException {
        DatagramPacket p = new DatagramPacket(buffer, buffer.length);
        try {
            socket.receive(p);
        } catch (SocketTimeoutException e) {
            return null;
        } catch (SocketException e) {
            if (!open) {
                return null;
            }
            throw e;
        }
        return new Received(this, p.getSocketAddress(), Arrays.copyOf(p.getData(), p.getLength()), true);
    }

    @Override
    protected void closeTransport() {
        socket.close();
    }
}
