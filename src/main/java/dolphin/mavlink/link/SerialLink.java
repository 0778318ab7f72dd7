package dolphin.mavlink.link;

import com.fazecast.jSerialComm.SerialPort;
import com.fazecast.jSerialComm.SerialPortInvalidPortException;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.util.Arrays;

/** A serial port (telemetry radio, USB) through jSerialComm. */
final class SerialLink extends Link {

    /** Serial ports have no socket address; this stands for the port in peer maps. */
    private final SocketAddress peer;
    private final SerialPort port;
    private final byte[] buffer = new byte[4096];

    SerialLink(LinkUrl url, int index) throws IOException {
        super(url, index);
        peer = InetSocketAddress.createUnresolved(url.device(), 0);
        try {
            port = SerialPort.getCommPort(url.device());
        } catch (SerialPortInvalidPortException e) {
            throw new IOException("no serial port " + url.device() + ": " + e.getMessage(), e);
        }
        port.setComPortParameters(url.baud(), 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, 500, 0);
        if (!port.openPort()) {
            throw new IOException("cannot open serial port " + url.device() + " (does it exist, and may this user open it?)");
        }
    }

    @Override
    public boolean datagrams() {
        return false;
    }

    @Override
    public SocketAddress fixedPeer() {
        return peer;
    }

    @Override
    public void send(byte[] frame, SocketAddress to) throws IOException {
        if (port.writeBytes(frame, frame.length) != frame.length) {
            throw new IOException("short write to " + url());
        }
    }

    @Override
    protected Received receive() throws IOException {
        int n = port.readBytes(buffer, buffer.length);
        if (n < 0) {
            throw new IOException("read error on " + url());
        }
        return n == 0 ? null : new Received(this, peer, Arrays.copyOf(buffer, n), false);
    }

    @Override
    protected void closeTransport() {
        port.closePort();
    }
}
