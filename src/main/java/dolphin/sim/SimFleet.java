package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.Clock;
import dolphin.core.Position;
import dolphin.mavlink.codec.DropCounters;
import dolphin.mavlink.codec.FrameReader;
import dolphin.mavlink.codec.FrameWriter;
import dolphin.mavlink.codec.SigningKey;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.PriorityQueue;
import java.util.Random;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A fleet of simulated ArduPilot vehicles on real UDP sockets, like SITL instances started with
 * {@code --serial0 udpclient:GCS}: each vehicle sends from its own port to a ground-station address
 * and answers there. One thread and one selector serve every vehicle, so hundreds fit
 * in one process; time comes from the given clock, which may run faster than real time.
 */
public final class SimFleet implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(SimFleet.class);
    private static final long TICK = 50_000_000L;

    /**
     * @param gcs ground-station addresses, one per link; the vehicles are split over them in
     *     contiguous blocks of {@link #perLink()}, like SITL instances sent to several ports
     * @param firstSysid system id of the first vehicle; ids count up from it across the fleet
     *     while they fit in 1..255, and start again from it on each link when they do not
     *     (MAVLink allows 255 systems per network; a ground station tells the links apart)
     * @param spacingMetres vehicles start this far apart, in a line to the east of {@code home}
     * @param equipment the sensors and cameras, by system id
     */
    public record Config(int count, VehicleKind kind, Position home, double spacingMetres, int firstSysid,
                         List<InetSocketAddress> gcs, SimOptions options, SigningKey signingKey, FaultModel faults,
                         SimEquipment equipment) {

        /** The Serra da Estrela base of the report's test. */
        public static final Position DEFAULT_HOME = Position.fromDegrees(40.444233, -7.375234, 820);
        public static final double DEFAULT_SPACING = 10;

        public Config {
            gcs = List.copyOf(gcs);
            Objects.requireNonNull(equipment, "equipment");
            if (count < 1) {
                throw new IllegalArgumentException("the fleet needs at least one vehicle, got " + count);
            }
            if (gcs.isEmpty()) {
                throw new IllegalArgumentException("the fleet needs a ground-station address");
            }
            if (firstSysid < 1 || firstSysid > 255) {
                throw new IllegalArgumentException("the first system id must lie in 1..255, got " + firstSysid);
            }
            if (!uniqueSysids(firstSysid, count) && firstSysid + perLink(count, gcs.size()) - 1 > 255) {
                int ids = 256 - firstSysid;
                throw new IllegalArgumentException(count + " vehicles from system id " + firstSysid + " need at least "
                        + (count + ids - 1) / ids + " links (" + ids + " system ids per link), got " + gcs.size());
            }
        }

        /** How many vehicles share one ground-station address (the last one may have fewer). */
        public int perLink() {
            return perLink(count, gcs.size());
        }

        private static int perLink(int count, int links) {
            return (count + links - 1) / links;
        }

        private static boolean uniqueSysids(int firstSysid, int count) {
            return firstSysid + count - 1 <= 255;
        }

        /** Index into {@link #gcs()} of the i-th vehicle. */
        public int linkOf(int i) {
            return i / perLink();
        }

        /** System id of the i-th vehicle: unique in the fleet when ids allow, else unique per link. */
        public int sysidOf(int i) {
            return uniqueSysids(firstSysid, count) ? firstSysid + i : firstSysid + i % perLink();
        }

        public int highestSysid() {
            return uniqueSysids(firstSysid, count) ? firstSysid + count - 1 : firstSysid + perLink() - 1;
        }

        public static Config of(int count, VehicleKind kind, InetSocketAddress gcs) {
            return of(count, kind, List.of(gcs));
        }

        /** The defaults: the report's base as home, 10 m apart, system ids from 1, no signing, no faults, no sensors or cameras. */
        public static Config of(int count, VehicleKind kind, List<InetSocketAddress> gcs) {
            return new Config(count, kind, DEFAULT_HOME, DEFAULT_SPACING, 1, gcs, SimOptions.DEFAULT, null, FaultModel.NONE,
                    SimEquipment.NONE);
        }

        public Config withOptions(SimOptions o) {
            return new Config(count, kind, home, spacingMetres, firstSysid, gcs, o, signingKey, faults, equipment);
        }

        public Config withFaults(FaultModel f) {
            return new Config(count, kind, home, spacingMetres, firstSysid, gcs, options, signingKey, f, equipment);
        }

        public Config withSigningKey(SigningKey k) {
            return new Config(count, kind, home, spacingMetres, firstSysid, gcs, options, k, faults, equipment);
        }

        public Config withFirstSysid(int sysid) {
            return new Config(count, kind, home, spacingMetres, sysid, gcs, options, signingKey, faults, equipment);
        }

        public Config withHome(Position p) {
            return new Config(count, kind, p, spacingMetres, firstSysid, gcs, options, signingKey, faults, equipment);
        }

        public Config withEquipment(SimEquipment e) {
            return new Config(count, kind, home, spacingMetres, firstSysid, gcs, options, signingKey, faults, e);
        }
    }

    private record Delayed(long at, long order, Runnable action) {
    }

    private final class Member {
        final SimVehicle vehicle;
        final DatagramChannel channel;
        final SocketAddress gcs;
        final FrameReader reader;
        final FrameWriter writer;

        Member(SimVehicle vehicle, DatagramChannel channel, SocketAddress gcs) {
            this.vehicle = vehicle;
            this.channel = channel;
            this.gcs = gcs;
            this.reader = new FrameReader(config.signingKey(), drops);
            this.writer = new FrameWriter(vehicle.sysid(), 1, config.signingKey(), 0);
        }
    }

    private final Config config;
    private final Clock clock;
    private final List<Member> members = new ArrayList<>();
    private final DropCounters drops = new DropCounters();
    private final PriorityQueue<Delayed> delayed = new PriorityQueue<>(
            (a, b) -> a.at != b.at ? Long.compare(a.at, b.at) : Long.compare(a.order, b.order));
    private final ConcurrentLinkedQueue<Runnable> tasks = new ConcurrentLinkedQueue<>();
    private final Random random;
    private final ByteBuffer buffer = ByteBuffer.allocate(65535);
    private Selector selector;
    private Thread thread;
    private volatile boolean running;
    private long order;

    public SimFleet(Config config, Clock clock) {
        this.config = config;
        this.clock = clock;
        this.random = new Random(config.faults().seed());
    }

    public synchronized void start() throws IOException {
        selector = Selector.open();
        long now = clock.nanoTime();
        for (int i = 0; i < config.count(); i++) {
            Position home = config.home().displace(0, i * config.spacingMetres(), 0);
            SimVehicle v = new SimVehicle(config.sysidOf(i), config.kind(), home, config.options(), now, config.equipment());
            DatagramChannel ch = DatagramChannel.open();
            ch.bind(new InetSocketAddress(0));
            ch.configureBlocking(false);
            Member m = new Member(v, ch, config.gcs().get(config.linkOf(i)));
            ch.register(selector, SelectionKey.OP_READ, m);
            v.connect(msg -> emit(m, msg));
            members.add(m);
        }
        running = true;
        thread = new Thread(this::loop, "sim-fleet");
        thread.setDaemon(true);
        thread.start();
        LOG.info("simulated fleet: {} {} {}(s) sending to {}", config.count(), config.options().autopilot(), config.kind(), config.gcs());
    }

    public List<SimVehicle> vehicles() {
        return members.stream().map(m -> m.vehicle).toList();
    }

    /** The vehicle with this system id; the first one when ids repeat over several links. */
    public SimVehicle vehicle(int sysid) {
        return member(sysid).vehicle;
    }

    /** The local UDP port a vehicle sends from; the first one's when ids repeat over several links. */
    public int port(int sysid) throws IOException {
        return ((InetSocketAddress) member(sysid).channel.getLocalAddress()).getPort();
    }

    private Member member(int sysid) {
        return members.stream().filter(m -> m.vehicle.sysid() == sysid).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no simulated vehicle with system id " + sysid));
    }

    /** What the vehicles' readers dropped (bad signatures, unsigned frames when signing, ...). */
    public DropCounters drops() {
        return drops;
    }

    /** Runs an action on the fleet's thread. */
    public void execute(Runnable action) {
        tasks.add(action);
        Selector s = selector;
        if (s != null) {
            s.wakeup();
        }
    }

    private void emit(Member m, MAVLinkMessage msg) {
        byte[] frame = m.writer.write(msg);
        deliver(() -> send(m, frame));
    }

    /** Applies the fault model to one datagram, in either direction. */
    private void deliver(Runnable action) {
        if (config.faults().none()) {
            action.run();
            return;
        }
        long now = clock.nanoTime();
        for (double d : config.faults().deliveries(random)) {
            if (d == 0) {
                action.run();
            } else {
                delayed.add(new Delayed(now + (long) (d * 1e9), order++, action));
            }
        }
    }

    private void send(Member m, byte[] frame) {
        try {
            m.channel.send(ByteBuffer.wrap(frame), m.gcs);
        } catch (IOException e) {
            LOG.debug("vehicle {}: send failed: {}", m.vehicle.sysid(), e.getMessage());
        }
    }

    private void loop() {
        long nextTick = clock.nanoTime();
        while (running) {
            try {
                long now = clock.nanoTime();
                long next = Math.min(nextTick, delayed.isEmpty() ? Long.MAX_VALUE : delayed.peek().at);
                long realMillis = Math.max(0, clock.realNanos(next - now) / 1_000_000);
                if (realMillis > 0) {
                    selector.select(realMillis);
                } else {
                    selector.selectNow();
                }
                for (SelectionKey key : selector.selectedKeys()) {
                    receive((Member) key.attachment());
                }
                selector.selectedKeys().clear();
                for (Runnable t; (t = tasks.poll()) != null; ) {
                    t.run();
                }
                now = clock.nanoTime();
                while (!delayed.isEmpty() && delayed.peek().at <= now) {
                    delayed.poll().action.run();
                }
                if (now >= nextTick) {
                    for (Member m : members) {
                        m.vehicle.tick(now);
                    }
                    nextTick = Math.max(nextTick + TICK, now - TICK);
                }
            } catch (IOException | RuntimeException e) {
                if (running) {
                    LOG.warn("simulated fleet: {}", e.toString(), e);
                }
            }
        }
    }

    private void receive(Member m) throws IOException {
        while (true) {
            buffer.clear();
            SocketAddress from = m.channel.receive(buffer);
            if (from == null) {
                return;
            }
            byte[] bytes = java.util.Arrays.copyOf(buffer.array(), buffer.position());
            deliver(() -> {
                m.reader.feed(bytes, 0, bytes.length, f -> handle(m, f.message()));
                m.reader.endOfPacket(f -> handle(m, f.message()));
            });
        }
    }

    private void handle(Member m, MAVLinkMessage msg) {
        if (msg != null) {
            m.vehicle.handle(msg, clock.nanoTime());
        }
    }

    @Override
    public void close() {
        running = false;
        if (selector != null) {
            selector.wakeup();
        }
        if (thread != null) {
            try {
                thread.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        for (Member m : members) {
            try {
                m.channel.close();
            } catch (IOException e) {
                LOG.debug("closing a vehicle socket: {}", e.getMessage());
            }
        }
        try {
            if (selector != null) {
                selector.close();
            }
        } catch (IOException e) {
            LOG.debug("closing the selector: {}", e.getMessage());
        }
    }
}
