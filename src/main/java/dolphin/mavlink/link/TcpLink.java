package dolphin.mavlink.link;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketAddress;
import java.net.SocketTimeoutException;
import java.util.Arrays;

/**
 * A TCP client (e.g. ArduPilot SITL's SERIAL0 on port 5760 + 10 x instance). When the connection
 * drops, the reader reconnects.
 */
final class TcpLink extends Link {

    private final InetSocketAddress remote;
    private final byte[] buffer = new byte[8192];
    private volatile Socket socket;

    TcpLink(LinkUrl url, int index) throws IOException {
        super(url, index);
        remote = url.address();
        if (remote.isUnresolved()) {
            throw new IOException("cannot resolve the host of " + url);
        }
        socket = connect();
    }

    private Socket connect() throws IOException {
        Socket s = new Socket();
        try {
            s.connect(remote, 5000);
            s.setSoTimeout(500);
            s.setTcpNoDelay(true);
            return s;
        } catch (IOException e) {
            s.close();
            throw new IOException("cannot connect to " + url() + ": " + e.getMessage(), e);
        }
    }

    @Override
    public boolean datagrams() {
        return false;
    }

    @Override
    public SocketAddress fixedPeer() {
        return remote;
    }

    @Override
    public synchronized void send(byte[] frame, SocketAddress peer) throws IOException {
        socket.getOutputStream().write(frame);
    }

    @Override
    protected Received receive() throws IOException {
        Socket s = socket;
        if (s.isClosed()) {
            socket = connect();
            return null;
        }
        InputStream in = s.getInputStream();
        int n;
        try {
            n = in.read(buffer);
        } catch (SocketTimeoutException e) {
            return null;
        }
        if (n < 0) {
            s.close();
            throw new IOException("connection closed by the peer; reconnecting");
        }
        return new Received(this, remote, Arrays.copyOf(buffer, n), false);
    }

    @Override
    protected void closeTransport() throws IOException {
        socket.close();
    }
}
