package dolphin.mavlink.link;

import java.io.Closeable;
import java.io.IOException;
import java.net.SocketAddress;
import java.util.function.Consumer;

/**
 * A transport for MAVLink frames. A link's reader thread only moves received bytes to a sink (the
 * communications thread); sending is done by the communications thread.
 */
public abstract class Link implements Closeable {

    /** Bytes received from {@code peer}; {@code datagram} is true when they are one whole datagram. */
    public record Received(Link link, SocketAddress peer, byte[] bytes, boolean datagram) {
    }

    private final LinkUrl url;
    private final int index;
    private volatile Consumer<Received> sink = r -> { };
    private volatile Consumer<String> problems = p -> { };
    private Thread reader;
    protected volatile boolean open = true;

    protected Link(LinkUrl url, int index) {
        this.url = url;
        this.index = index;
    }

    public static Link open(LinkUrl url, int index) throws IOException {
        return switch (url.kind()) {
            case UDPIN, UDPOUT -> new UdpLink(url, index);
            case TCP -> new TcpLink(url, index);
            case SERIAL -> new SerialLink(url, index);
        };
    }

    public LinkUrl url() {
        return url;
    }

    /** The link's position in the communications' list; also its signing link id. */
    public int index() {
        return index;
    }

    /** The local port of a socket link (useful when the URL asked for port 0); -1 for others. */
    public int localPort() {
        return -1;
    }

    /** Whether each receive is a whole datagram (frames never span two). */
    public abstract boolean datagrams();

    /** Starts the reader thread, which hands received bytes to {@code sink} and problems to {@code problems}. */
    public final void start(Consumer<Received> sink, Consumer<String> problems) {
        this.sink = sink;
        this.problems = problems;
        reader = new Thread(this::readLoop, "mavlink-link-" + index + " " + url);
        reader.setDaemon(true);
        reader.start();
    }

    /** Sends one frame to a peer (ignored by links with one fixed peer, which send to it). */
    public abstract void send(byte[] frame, SocketAddress peer) throws IOException;

    /** The peer a link with one fixed endpoint talks to; null for links that learn peers. */
    public abstract SocketAddress fixedPeer();

    /** Blocks until bytes arrive or the link closes; returns null when there is nothing (timeout). */
    protected abstract Received receive() throws IOException;

    private void readLoop() {
        while (open) {
            try {
                Received r = receive();
                if (r != null) {
                    sink.accept(r);
                }
            } catch (IOException | RuntimeException e) {
                if (open) {
                    problems.accept(url + ": " + e.getMessage());
                    pauseAfterError();
                }
            }
        }
    }

    /** Waits a little after a read error so a broken link does not spin. */
    protected void pauseAfterError() {
        try {
            Thread.sleep(200);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            open = false;
        }
    }

    @Override
    public void close() throws IOException {
        open = false;
        closeTransport();
        if (reader != null) {
            try {
                reader.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    protected abstract void closeTransport() throws IOException;

    @Override
    public String toString() {
        return url.toString();
    }
}
