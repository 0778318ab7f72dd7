package dolphin.mavlink;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.mavlink.codec.Frame;
import dolphin.mavlink.codec.FrameReader;
import dolphin.mavlink.link.Link;
import dolphin.mavlink.link.LinkUrl;
import java.io.IOException;
import java.lang.reflect.Field;
import java.net.SocketAddress;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Relays vehicle traffic to viewers (QGroundControl, MAVProxy) the way MAVProxy's {@code --out}
 * does: every frame a vehicle sends goes, unchanged, to each viewer link, so the viewer sees the
 * vehicles with their own ids and signatures; frames a viewer sends go unchanged to the vehicle
 * they target (to every vehicle when they target none), so its map, parameter and mission screens
 * work. Replies to a viewer's requests come back through the same relay; the runtime itself ignores
 * command acknowledgements addressed to another ground station.
 */
public final class Forwarder implements MAVLinkCommunications.FrameObserver, AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(Forwarder.class);
    private static final Map<Class<?>, Optional<Field>> TARGETS = new ConcurrentHashMap<>();

    private final MAVLinkCommunications comms;
    private final List<LinkUrl> urls;
    private final List<Viewer> viewers = new ArrayList<>();
    private final AtomicLong toViewers = new AtomicLong();
    private final AtomicLong fromViewers = new AtomicLong();

    /** One viewer link: the peers it learned (for udpin) and its own frame reader. */
    private static final class Viewer {
        final Link link;
        final FrameReader reader = new FrameReader();
        final Set<SocketAddress> peers = new LinkedHashSet<>();

        Viewer(Link link) {
            this.link = link;
        }
    }

    public Forwarder(MAVLinkCommunications comms, List<LinkUrl> urls) {
        this.comms = comms;
        this.urls = List.copyOf(urls);
    }

    /** Opens the viewer links and starts relaying; throws with the link's name when one cannot be opened. */
    public void start() throws IOException {
        for (LinkUrl url : urls) {
            Viewer v;
            try {
                v = new Viewer(Link.open(url, comms.links().size() + viewers.size()));
            } catch (IOException e) {
                close();
                throw new IOException("--forward " + url + ": " + e.getMessage(), e);
            }
            viewers.add(v);
        }
        for (Viewer v : viewers) {
            v.link.start(r -> comms.execute(() -> fromViewer(v, r)), problem -> LOG.warn("forward link {}", problem));
        }
        comms.addObserver(this);
    }

    /** Frames relayed to viewers so far (one per viewer peer). */
    public long framesToViewers() {
        return toViewers.get();
    }

    /** Frames from viewers relayed to vehicles so far (one per vehicle). */
    public long framesFromViewers() {
        return fromViewers.get();
    }

    /** Runs on the communications thread for every frame in and out; relays what vehicles send. */
    @Override
    public void frame(boolean incoming, Link link, Frame frame) {
        if (!incoming) {
            return;
        }
        for (Viewer v : viewers) {
            if (v.link.fixedPeer() != null) {
                send(v, frame.raw(), v.link.fixedPeer());
            } else {
                for (SocketAddress peer : v.peers) {
                    send(v, frame.raw(), peer);
                }
            }
        }
    }

    private void send(Viewer v, byte[] bytes, SocketAddress peer) {
        try {
            v.link.send(bytes, peer);
            toViewers.incrementAndGet();
        } catch (IOException e) {
            LOG.debug("forward to {} on {} failed: {}", peer, v.link, e.getMessage());
        }
    }

    /** On the communications thread: a viewer's bytes, relayed frame by frame to the vehicles they target. */
    private void fromViewer(Viewer v, Link.Received r) {
        v.peers.add(r.peer());
        v.reader.feed(r.bytes(), 0, r.bytes().length, this::toVehicles);
        if (r.datagram()) {
            v.reader.endOfPacket(this::toVehicles);
        }
    }

    private void toVehicles(Frame frame) {
        int target = targetSystem(frame);
        for (MAVLinkNode node : comms.nodes()) {
            if (target == 0 || node.getMavLinkId() == target) {
                comms.sendRawOnCommsThread(node, frame.raw());
                fromViewers.incrementAndGet();
            }
        }
    }

    /** The frame's target_system field, or 0 for a broadcast (no such field, or unknown message). */
    static int targetSystem(Frame frame) {
        MAVLinkMessage m = frame.message();
        if (m == null) {
            return 0;
        }
        Optional<Field> f = TARGETS.computeIfAbsent(m.getClass(), c -> {
            try {
                return Optional.of(c.getField("target_system"));
            } catch (NoSuchFieldException e) {
                return Optional.empty();
            }
        });
        try {
            return f.isEmpty() ? 0 : ((Number) f.get().get(m)).intValue();
        } catch (IllegalAccessException e) {
            return 0;
        }
    }

    @Override
    public void close() {
        for (Viewer v : viewers) {
            try {
                v.link.close();
            } catch (IOException e) {
                LOG.debug("closing {}: {}", v.link, e.getMessage());
            }
        }
    }
}
