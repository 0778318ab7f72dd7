package dolphin.bench;

import com.MAVLink.common.msg_named_value_float;
import dolphin.mavlink.codec.FrameWriter;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketException;

/**
 * Every vehicle's companion computer (component 191) sending readings as fast as a misbehaving one
 * would: RATE NAMED_VALUE_FLOAT "FLOOD" per second per vehicle, in 10 ms bursts, to the runtime's port.
 */
final class ReadingFlood implements AutoCloseable {

    private static final int COMPANION = 191;

    private final Thread thread;
    private volatile boolean running = true;

    private ReadingFlood(int vehicles, int rate, int port) throws SocketException {
        DatagramSocket socket = new DatagramSocket();
        InetSocketAddress to = new InetSocketAddress("127.0.0.1", port);
        FrameWriter[] writers = new FrameWriter[vehicles];
        for (int i = 0; i < vehicles; i++) {
            writers[i] = new FrameWriter(i + 1, COMPANION, null, 0);
        }
        thread = new Thread(() -> {
            msg_named_value_float m = new msg_named_value_float();
            m.setName("FLOOD");
            double owed = 0;
            long last = System.nanoTime();
            try (socket) {
                while (running) {
                    long now = System.nanoTime();
                    owed += (now - last) / 1e9 * rate;
                    last = now;
                    for (; owed >= 1; owed--) {
                        m.value = (float) Math.random();
                        for (FrameWriter w : writers) {
                            byte[] frame = w.write(m);
                            socket.send(new DatagramPacket(frame, frame.length, to));
                        }
                    }
                    Thread.sleep(10);
                }
            } catch (Exception e) {
                if (running) {
                    System.err.println("reading flood stopped: " + e);
                }
            }
        }, "reading flood");
        thread.setDaemon(true);
        thread.start();
    }

    static ReadingFlood start(int vehicles, int rate, int port) throws SocketException {
        return new ReadingFlood(vehicles, rate, port);
    }

    @Override
    public void close() throws InterruptedException {
        running = false;
        thread.join(2000);
    }
}
