package dolphin.mavlink;

import dolphin.mavlink.codec.MessageTable;
import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.ardupilotmega.msg_ekf_status_report;
import com.MAVLink.ardupilotmega.msg_radio;
import com.MAVLink.common.msg_fence_status;
import com.MAVLink.common.msg_command_ack;
import com.MAVLink.common.msg_param_error;
import com.MAVLink.common.msg_param_value;
import com.MAVLink.common.msg_command_long;
import com.MAVLink.common.msg_extended_sys_state;
import com.MAVLink.standard.msg_autopilot_version;
import com.MAVLink.common.msg_home_position;
import com.MAVLink.common.msg_mission_current;
import com.MAVLink.common.msg_radio_status;
import com.MAVLink.common.msg_statustext;
import com.MAVLink.common.msg_sys_status;
import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_STATE;
import com.MAVLink.enums.MAV_TYPE;
import com.MAVLink.minimal.msg_heartbeat;
import com.MAVLink.standard.msg_global_position_int;
import dolphin.core.Clock;
import dolphin.core.Position;
import dolphin.core.VehicleEvent;
import dolphin.mavlink.codec.DropCounters;
import dolphin.mavlink.codec.Frame;
import dolphin.mavlink.codec.FrameReader;
import dolphin.mavlink.codec.FrameWriter;
import dolphin.mavlink.link.Link;
import java.io.IOException;
import java.net.SocketAddress;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Function;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The ground station's one MAVLink thread. Link reader threads hand it bytes;
 * it decodes frames, discovers vehicles, routes messages through the {@link MessageHandler} to
 * their {@link MAVLinkNode}, sends everything that goes out, and runs the timers: the 1 Hz GCS
 * heartbeat, command retries, telemetry re-requests and each vehicle's {@link Contact}, whose changes
 * it publishes as {@link VehicleEvent}s. Other threads talk to it through a queue.
 */
public final class MAVLinkCommunications implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(MAVLinkCommunications.class);
    private static final long SECOND = 1_000_000_000L;
    /** GLOBAL_POSITION_INT.hdg when the vehicle does not know its heading (UINT16_MAX). */
    private static final int UNKNOWN_HEADING = 65535;

    /** Sees every frame in and out, on the communications thread (for forwarding, logs and tests). */
    public interface FrameObserver {
        void frame(boolean incoming, Link link, Frame frame);
    }

    /**
     * Sees every decoded message from every component of a discovered vehicle (its autopilot, a
     * camera, a companion computer), on the communications thread: how sensors and payloads are read.
     */
    public interface ComponentListener {
        void message(MAVLinkNode node, int component, MAVLinkMessage message);
    }

    private final MAVLinkConfig config;
    private final Clock clock;
    private final List<Link> links = new ArrayList<>();
    private final Map<Link, FrameReader> readers = new HashMap<>();
    private final Map<Link, FrameWriter> writers = new HashMap<>();
    private final Map<Link, Set<SocketAddress>> peers = new HashMap<>();
    private final Map<Link, LinkTraffic> traffic = new ConcurrentHashMap<>();
    private final Map<Link, LinkRequests> requestsInFlight = new ConcurrentHashMap<>();
    private final Map<String, MAVLinkNode> nodesByKey = new ConcurrentHashMap<>();
    private final Map<String, MAVLinkNode> nodesById = new ConcurrentHashMap<>();
    /** By LINK/SYSID: system ids heard on a link while known on another, not yet told apart. */
    private final Map<String, LinkCandidate> candidates = new HashMap<>();
    /** LINK/SYSID of candidates that turned out to be other vehicles, discovered as SYSID@LINK. */
    private final Set<String> otherVehicles = new HashSet<>();
    private final MessageHandler handler = new MessageHandler();
    private final DropCounters drops = new DropCounters();
    private final LinkedBlockingQueue<Object> queue = new LinkedBlockingQueue<>();
    private final Timers timers = new Timers();
    private final CommandSender commands;
    private final TelemetryRequests telemetry;
    private final ParameterReads parameters;
    private final CapabilityRequests capabilities;
    private final List<FrameObserver> observers = new CopyOnWriteArrayList<>();
    private final List<ComponentListener> componentListeners = new CopyOnWriteArrayList<>();
    private final List<Consumer<VehicleEvent>> vehicleEventListeners = new CopyOnWriteArrayList<>();
    private final AtomicLong framesIn = new AtomicLong();
    private final AtomicLong framesOut = new AtomicLong();
    private final AtomicLong filtered = new AtomicLong();
    private volatile Runnable telemetryListener = () -> { };
    private final Map<Class<?>, Object> extensions = new ConcurrentHashMap<>();
    private volatile boolean running;
    private Thread thread;
    private Tlog tlog;

    public MAVLinkCommunications(MAVLinkConfig config, Clock clock) {
        this.config = config;
        this.clock = clock;
        this.commands = new CommandSender(this::sendOnCommsThread, config.commandTimeout().toNanos(), config.commandAttempts());
        this.parameters = new ParameterReads(this::sendOnCommsThread, config.commandTimeout().toNanos(), config.commandAttempts());
        this.telemetry = new TelemetryRequests(this, config.telemetryHz());
        this.capabilities = CapabilityRequests.of(this);
        routeVehicleState();
    }

    public MAVLinkConfig config() {
        return config;
    }

    public Clock clock() {
        return clock;
    }

    /**
     * The one instance of {@code type} attached to these communications, made by {@code create} on
     * first use: how a layer above (missions) keeps its own state per communications and registers
     * for the messages it needs, without this layer knowing it.
     */
    public <T> T extension(Class<T> type, Function<MAVLinkCommunications, T> create) {
        return type.cast(extensions.computeIfAbsent(type, t -> create.apply(this)));
    }

    /** Wakes the script's task tree, as telemetry does (e.g. when a transfer or command completes). */
    public void wakeScript() {
        telemetryListener.run();
    }

    /** Opens the links and starts the thread. Throws with the link's name when one cannot be opened. */
    public synchronized void start() throws IOException {
        if (running) {
            return;
        }
        try {
            for (int i = 0; i < config.links().size(); i++) {
                attach(Link.open(config.links().get(i), i));
            }
            if (config.tlog() != null) {
                tlog = new Tlog(config.tlog());
            }
        } catch (IOException e) {
            closeLinks();
            throw e;
        }
        running = true;
        thread = new Thread(this::loop, "MAVLink communications");
        thread.setDaemon(true);
        thread.start();
        links.forEach(l -> l.start(queue::add, problem -> LOG.warn("link {}", problem)));
    }

    /** Makes an open link one of ours: {@link #start} does so with each link it opens, a spec with a fake link. */
    void attach(Link link) {
        DropCounters linkDrops = new DropCounters(drops);
        links.add(link);
        readers.put(link, new FrameReader(config.signingKey(), linkDrops));
        writers.put(link, new FrameWriter(config.sysid(), config.compid(), config.signingKey(), link.index()));
        peers.put(link, new LinkedHashSet<>());
        traffic.put(link, new LinkTraffic(link.url().toString(), linkDrops, clock.nanoTime()));
    }

    /**
     * For specs on a {@link dolphin.core.ManualClock}: takes {@code given} (fakes) as its links and
     * starts neither their readers nor its thread; the spec hands bytes in with {@link #received} and
     * does the thread's work with {@link #runDue}, on its own thread.
     */
    void attachForSpecs(List<Link> given) {
        given.forEach(this::attach);
        scheduleTicks();
    }

    /** For specs: bytes a link received, queued as a link's reader thread queues them. */
    void received(Link.Received bytes) {
        queue.add(bytes);
    }

    /** For specs: what the communications thread would do now, the queued work and the timers due. */
    void runDue() {
        for (Object event; (event = queue.poll()) != null; ) {
            handle(event);
        }
        timers.runDue(clock.nanoTime());
    }

    public List<Link> links() {
        return List.copyOf(links);
    }

    /** Every link's health now, in the order the links were given; from any thread. */
    public List<LinkHealth> linkHealth() {
        long now = clock.nanoTime();
        return links().stream().map(l -> traffic.get(l).health(now)).toList();
    }

    /** Whether a telemetry radio ever reported on the link. */
    boolean radioHeard(Link link) {
        LinkTraffic t = link == null ? null : traffic.get(link);
        return t != null && t.radioHeard();
    }

    /** The requests in flight on one link (a link of none: a count of its own). */
    LinkRequests linkRequests(Link link) {
        return link == null ? new LinkRequests() : requestsInFlight.computeIfAbsent(link, l -> new LinkRequests());
    }

    /** The health of one link now; a link these communications do not run has nothing counted. */
    LinkHealth linkHealth(Link link) {
        LinkTraffic t = link == null ? null : traffic.get(link);
        return t == null ? LinkHealth.unmeasured(link == null ? "" : link.toString()) : t.health(clock.nanoTime());
    }

    /** Every vehicle discovered so far, connected or not, by system id then the link it was discovered on. */
    public List<MAVLinkNode> nodes() {
        return nodesById.values().stream()
                .sorted(Comparator.comparingInt(MAVLinkNode::getMavLinkId).thenComparingInt(n -> n.links().first().index()))
                .toList();
    }

    public MAVLinkNode node(String id) {
        return nodesById.get(id);
    }

    /** The consumers of decoded messages from vehicles' autopilots; platforms add theirs (missions). */
    public MessageHandler messageHandler() {
        return handler;
    }

    public DropCounters drops() {
        return drops;
    }

    public long framesIn() {
        return framesIn.get();
    }

    public long framesOut() {
        return framesOut.get();
    }

    /** Frames from systems outside the allow-list. */
    public long filtered() {
        return filtered.get();
    }

    /** How often a vehicle's telemetry streams were asked for again after falling silent. */
    public int telemetryRerequests(String nodeId) {
        return telemetry.rerequests(nodeId);
    }

    /** Runs after each state update that conditions may read (position, battery, mode, mission). */
    public void setTelemetryListener(Runnable listener) {
        telemetryListener = listener == null ? () -> { } : listener;
    }

    public void addObserver(FrameObserver observer) {
        observers.add(observer);
    }

    public void addComponentListener(ComponentListener listener) {
        componentListeners.add(listener);
    }

    /**
     * Adds a receiver of every {@link VehicleEvent} these communications raise (contact lost and
     * regained, on the communications thread) or that a layer above publishes (on its own thread):
     * it must be thread-safe and quick, as it holds up the thread that raised the event.
     */
    public void addVehicleEventListener(Consumer<VehicleEvent> listener) {
        vehicleEventListeners.add(listener);
    }

    /**
     * Hands an event to every vehicle-event listener, on this thread, from any thread: how the link
     * layer and the layers above (missions) tell of what happens to a vehicle. A listener that throws
     * is logged and the others still hear of the event, so none can stop the communications thread.
     */
    public void publish(VehicleEvent event) {
        for (Consumer<VehicleEvent> l : vehicleEventListeners) {
            try {
                l.accept(event);
            } catch (RuntimeException e) {
                LOG.warn("a vehicle event listener failed on '{}'", event.line(), e);
            }
        }
    }

    /** Sends a message to a vehicle, from any thread. */
    public void send(MAVLinkNode node, MAVLinkMessage message) {
        execute(() -> sendOnCommsThread(node, message));
    }

    /** Sends a COMMAND_LONG and completes with its COMMAND_ACK, retrying on timeout; from any thread. */
    public CompletableFuture<CommandResult> command(MAVLinkNode node, int command, float... params) {
        CompletableFuture<CommandResult> result = new CompletableFuture<>();
        execute(() -> commandOnCommsThread(node, command, params).whenComplete((r, e) -> {
            if (e != null) {
                result.completeExceptionally(e);
            } else {
                result.complete(r);
            }
        }));
        return result;
    }

    /** Reads a parameter by name; completes empty when the vehicle did not answer. From any thread. */
    public CompletableFuture<OptionalDouble> parameter(MAVLinkNode node, String name) {
        CompletableFuture<OptionalDouble> result = new CompletableFuture<>();
        execute(() -> parameters.read(node, name, clock.nanoTime()).thenAccept(result::complete));
        return result;
    }

    void hurryCapabilities(MAVLinkNode node) {
        capabilities.hurry(node, clock.nanoTime());
    }

    /** Runs an action on the communications thread. */
    public void execute(Runnable action) {
        queue.add(action);
    }

    /**
     * Runs an action on the communications thread after {@code delay} of clock time (protocol
     * timeouts). Callable from any thread; to cancel, let the action check whether it is still due.
     */
    public void schedule(java.time.Duration delay, Runnable action) {
        execute(() -> timers.at(clock.nanoTime() + delay.toNanos(), action));
    }

    CompletableFuture<CommandResult> commandOnCommsThread(MAVLinkNode node, int command, float... params) {
        msg_command_long m = new msg_command_long();
        m.target_system = (short) node.getMavLinkId();
        m.target_component = (short) node.getAutopilotCompid();
        m.command = command;
        float[] p = java.util.Arrays.copyOf(params, 7);
        m.param1 = p[0];
        m.param2 = p[1];
        m.param3 = p[2];
        m.param4 = p[3];
        m.param5 = p[4];
        m.param6 = p[5];
        m.param7 = p[6];
        return commands.submit(node, m, clock.nanoTime());
    }

    void sendOnCommsThread(MAVLinkNode node, MAVLinkMessage message) {
        transmit(node.getLink(), message, node.getAddress());
    }

    /** Sends a frame as it is (relayed from a viewer) to a vehicle; on the communications thread. */
    void sendRawOnCommsThread(MAVLinkNode node, byte[] frame) {
        try {
            node.getLink().send(frame, node.getAddress());
            framesOut.incrementAndGet();
            traffic.get(node.getLink()).sent(clock.nanoTime(), frame.length);
            log(frame);
        } catch (IOException e) {
            LOG.warn("relaying a frame to vehicle {} failed: {}", node.getId(), e.getMessage());
        }
    }

    private void transmit(Link link, MAVLinkMessage message, SocketAddress to) {
        byte[] frame = writers.get(link).write(message);
        try {
            link.send(frame, to);
            framesOut.incrementAndGet();
            traffic.get(link).sent(clock.nanoTime(), frame.length);
            log(frame);
            if (!observers.isEmpty()) {
                observeOutgoing(link, frame);
            }
        } catch (IOException e) {
            LOG.warn("sending {} on {} to {} failed: {}", MessageTable.get().name(message.msgid), link, to, e.getMessage());
        }
    }

    private void scheduleTicks() {
        long now = clock.nanoTime();
        timers.at(now, this::heartbeat);
        timers.at(now + SECOND / 2, this::supervise);
    }

    private void loop() {
        scheduleTicks();
        while (running) {
            try {
                long wait = Math.max(0, Math.min(timers.next() - clock.nanoTime(), SECOND));
                handle(queue.poll(Math.max(1, clock.realNanos(wait)), TimeUnit.NANOSECONDS));
                timers.runDue(clock.nanoTime());
            } catch (InterruptedException e) {
                running = false;
            } catch (RuntimeException e) {
                LOG.warn("communications: {}", e.toString(), e);
            }
        }
    }

    private void handle(Object event) {
        if (event instanceof Link.Received r) {
            receive(r);
        } else if (event instanceof Runnable action) {
            action.run();
        }
    }

    private void heartbeat() {
        msg_heartbeat hb = new msg_heartbeat();
        hb.type = MAV_TYPE.MAV_TYPE_GCS;
        hb.autopilot = MAV_AUTOPILOT.MAV_AUTOPILOT_INVALID;
        hb.system_status = MAV_STATE.MAV_STATE_ACTIVE;
        hb.mavlink_version = 3;
        for (Link link : links) {
            if (link.fixedPeer() != null) {
                transmit(link, hb, link.fixedPeer());
            } else {
                for (SocketAddress peer : peers.get(link)) {
                    transmit(link, hb, peer);
                }
            }
        }
        timers.at(clock.nanoTime() + config.heartbeatPeriod().toNanos(), this::heartbeat);
    }

    private void supervise() {
        long now = clock.nanoTime();
        commands.tick(now);
        parameters.tick(now);
        telemetry.check(now);
        capabilities.check(now);
        nodesById.values().forEach(n -> {
            if (n.wasConnected != n.isConnected()) {
                n.wasConnected = !n.wasConnected;
                LOG.info("vehicle {} {}", n.getId(), n.wasConnected ? "is back" : "lost: no heartbeat within " + n.getConnectionTimeout() + " s");
                if (n.wasConnected) {
                    capabilities.ask(n, now);
                }
                telemetryListener.run();
            }
            n.contact().check().ifPresent(this::publish);
        });
        candidates.values().removeIf(c -> c.isStale(now));
        timers.at(now + SECOND / 4, this::supervise);
    }

    /** Counts and decodes what a link's reader handed over; on the communications thread, or a spec's in its place. */
    void receive(Link.Received r) {
        traffic.get(r.link()).received(clock.nanoTime(), r.bytes().length);
        FrameReader reader = readers.get(r.link());
        reader.feed(r.bytes(), 0, r.bytes().length, f -> onFrame(r.link(), r.peer(), f));
        if (r.datagram()) {
            reader.endOfPacket(f -> onFrame(r.link(), r.peer(), f));
        }
    }

    private void onFrame(Link link, SocketAddress peer, Frame frame) {
        framesIn.incrementAndGet();
        peers.get(link).add(peer);
        // every frame the link brought counts for its losses, a duplicate of another link's included
        noteOnLink(link, frame);
        String key = link.index() + "/" + frame.sysid();
        if (!nodesByKey.containsKey(key)) {
            tellApart(key, link, peer, frame);
        }
        MAVLinkNode node = nodesByKey.get(key);
        if (node != null && duplicate(node, link, peer, frame)) {
            return;
        }
        log(frame.raw());
        observers.forEach(o -> o.frame(true, link, frame));
        if (!config.allowedSysids().isEmpty() && !config.allowedSysids().contains(frame.sysid())) {
            filtered.incrementAndGet();
            return;
        }
        MAVLinkMessage message = frame.message();
        if (message == null) {
            return;
        }
        if (node == null && message instanceof msg_heartbeat hb && !candidates.containsKey(key)) {
            node = discover(link, peer, frame, hb);
        }
        if (node != null) {
            process(node, frame, message);
        }
    }

    private void process(MAVLinkNode node, Frame frame, MAVLinkMessage message) {
        tellComponentListeners(node, frame.compid(), message);
        if (frame.compid() != node.getAutopilotCompid()) {
            return;
        }
        node.contact().heard(frame.msgid()).ifPresent(this::publish);
        telemetry.seen(node, frame.msgid(), clock.nanoTime());
        handler.dispatch(node, message);
    }

    /**
     * Counts the frame for its link's losses and keeps a telemetry radio's report, whoever sent it
     * and whatever the allow-list: a radio's report tells of the link, so it makes no vehicle and is
     * no sign of one's life (docs/decisions.md, "Link health").
     */
    private void noteOnLink(Link link, Frame frame) {
        LinkTraffic t = traffic.get(link);
        t.frame(frame.sysid(), frame.compid(), frame.seq());
        if (frame.msgid() == msg_radio_status.MAVLINK_MSG_ID_RADIO_STATUS && frame.message() instanceof msg_radio_status m) {
            t.radio(RadioStatus.of(m, clock.nanoTime()));
        } else if (frame.msgid() == msg_radio.MAVLINK_MSG_ID_RADIO && frame.message() instanceof msg_radio m) {
            t.radio(RadioStatus.of(m, clock.nanoTime()));
        }
    }

    /**
     * Whether a frame of a known vehicle is a duplicate that another of its links brought already. On
     * the way, a sign of its life on this link, which may change the link it is sent to through, and a
     * frame to compare with any link not yet told apart from it.
     */
    private boolean duplicate(MAVLinkNode node, Link link, SocketAddress peer, Frame frame) {
        long now = clock.nanoTime();
        VehicleLinks vehicleLinks = node.links();
        if (frame.compid() == node.getAutopilotCompid() && Contact.isSignOfLife(frame.msgid())) {
            vehicleLinks.heard(link, peer, now).ifPresent(change -> linkChanged(node, change));
        }
        if (vehicleLinks.duplicate(link, frame, now)) {
            return true;
        }
        if (!candidates.isEmpty()) {
            for (Link other : links) {
                LinkCandidate candidate = candidates.get(other.index() + "/" + frame.sysid());
                if (candidate != null) {
                    candidate.heardKnown(node, link, frame, now);
                    joinIfSame(candidate);
                }
            }
        }
        return false;
    }

    /**
     * A frame of a system not discovered on this link. While a vehicle with its id is known on another
     * link, the link is a {@link LinkCandidate} until told apart: it joins that vehicle, or it brings
     * another vehicle, discovered at its last heartbeat. Till then its frames are logged and relayed
     * as any undiscovered system's, and processed by none.
     */
    private void tellApart(String key, Link link, SocketAddress peer, Frame frame) {
        if (otherVehicles.contains(key) || !nodesById.containsKey(String.valueOf(frame.sysid()))) {
            return;
        }
        long now = clock.nanoTime();
        LinkCandidate candidate = candidates.computeIfAbsent(key,
                k -> new LinkCandidate(link, frame.sysid(), i -> nodesByKey.get(i + "/" + frame.sysid()), now));
        candidate.heardHere(frame, peer, now);
        if (joinIfSame(candidate) || !candidate.isOther(now)) {
            return;
        }
        candidates.remove(key);
        otherVehicles.add(key);
        LOG.info("system {} on {} is another vehicle than the one on {}: no frames with a time in common in {} s", frame.sysid(),
                link, node(String.valueOf(frame.sysid())).getLink(), LinkCandidate.DECIDE_WITHIN / SECOND);
        // The frame at hand, a heartbeat or not, is processed next; an earlier heartbeat first.
        Frame heartbeat = candidate.heartbeat();
        if (heartbeat != null && heartbeat != frame && heartbeat.message() instanceof msg_heartbeat hb) {
            MAVLinkNode node = discover(link, candidate.peer(), heartbeat, hb);
            if (node != null) {
                process(node, heartbeat, hb);
            }
        }
    }

    /** Makes the candidate's link one of the vehicle's when it has shown itself to be it. */
    private boolean joinIfSame(LinkCandidate candidate) {
        MAVLinkNode node = candidate.same();
        if (node == null) {
            return false;
        }
        Link link = candidate.link();
        String key = link.index() + "/" + candidate.sysid();
        candidates.remove(key);
        node.links().join(link, candidate.peer(), clock.nanoTime(), candidate.processedFrames());
        nodesByKey.put(key, node);
        linkChanged(node, "also heard on " + link + ", the same frames as on " + node.getLink());
        return true;
    }

    private void linkChanged(MAVLinkNode node, String change) {
        LOG.info("vehicle {}: {}", node.getId(), change);
        publish(new VehicleEvent(node.getId(), VehicleEvent.EventKind.LINK_CHANGED, change, clock.seconds()));
    }

    private void tellComponentListeners(MAVLinkNode node, int component, MAVLinkMessage message) {
        for (ComponentListener l : componentListeners) {
            try {
                l.message(node, component, message);
            } catch (RuntimeException e) {
                LOG.warn("reading {} from component {} of vehicle {} failed", MessageTable.get().name(message.msgid), component,
                        node.getId(), e);
            }
        }
    }

    private MAVLinkNode discover(Link link, SocketAddress peer, Frame frame, msg_heartbeat hb) {
        String type = DolphinType.of(hb.type, hb.autopilot);
        if (type == null) {
            return null;
        }
        // The plain system id while it is unique; a later vehicle with the same id on another link
        // is SYSID@LINK, LINK counting the links from 1 in the order they were given.
        String plain = String.valueOf(frame.sysid());
        String id = nodesById.containsKey(plain) ? plain + "@" + (link.index() + 1) : plain;
        Autopilot autopilot = Autopilot.of(hb.autopilot);
        VehicleFamily family = VehicleFamily.of(hb.type, hb.autopilot);
        MAVLinkNode node = new MAVLinkNode(id, type, this, link, peer, frame.sysid(), frame.compid(), autopilot, family, clock);
        nodesByKey.put(link.index() + "/" + frame.sysid(), node);
        nodesById.put(id, node);
        LOG.info("discovered vehicle {} ({}, {}) on {} at {}", id, type, autopilot.label(family), link, peer);
        telemetry.discovered(node, clock.nanoTime());
        capabilities.ask(node, clock.nanoTime());
        return node;
    }

    /** The consumers that keep each node's {@link VehicleState} up to date. */
    private void routeVehicleState() {
        handler.on(msg_heartbeat.class, (n, hb) -> changed(n, s -> s.withHeartbeat(hb, clock.nanoTime())));
        handler.on(msg_sys_status.class, (n, m) -> changed(n, s -> s.withSystemStatus(m, clock.nanoTime())));
        // ArduPilot sends 0, 0 until its EKF has a position estimate: that is no position yet.
        handler.on(msg_global_position_int.class, (n, m) -> changed(n, s -> s.withPosition(m.lat == 0 && m.lon == 0 ? null
                : Position.fromDegrees(m.lat * 1e-7, m.lon * 1e-7, m.alt * 1e-3), m.relative_alt * 1e-3,
                m.hdg == UNKNOWN_HEADING ? Double.NaN : m.hdg / 100.0, clock.nanoTime()).withBootTime(m.time_boot_ms)));
        handler.on(msg_home_position.class, (n, m) -> changed(n, s -> s.withHome(
                Position.fromDegrees(m.latitude * 1e-7, m.longitude * 1e-7, m.altitude * 1e-3))));
        handler.on(msg_extended_sys_state.class, (n, m) -> changed(n, s -> s.withExtendedState(m.landed_state, m.vtol_state)));
        handler.on(msg_mission_current.class, (n, m) -> changed(n, s -> s.withMissionCurrent(m.seq, m.total, m.mission_state, m.mission_id)));
        handler.on(msg_ekf_status_report.class, (n, m) -> changed(n, s -> s.withEkfFlags(m.flags)));
        handler.on(msg_fence_status.class, (n, m) -> changed(n, s -> s.withFenceBreached(m.breach_status != 0)));
        handler.on(msg_autopilot_version.class, (n, m) -> {
            n.capabilities(m.capabilities);
            capabilities.answered(n);
        });
        handler.on(msg_statustext.class, (n, m) -> {
            String text = StatusText.of(m);
            LOG.info("vehicle {}: {}", n.getId(), text);
            changed(n, s -> s.withStatusText(text));
        });
        handler.on(msg_param_value.class, parameters::onValue);
        handler.on(msg_param_error.class, parameters::onError);
        handler.on(msg_command_ack.class, (n, m) -> {
            // Acknowledgements of another ground station's commands (a viewer's, relayed) are not ours.
            if (m.target_system == 0 || m.target_system == config.sysid()) {
                commands.onAck(n, m, clock.nanoTime());
            }
        });
    }

    private void changed(MAVLinkNode node, java.util.function.UnaryOperator<VehicleState> change) {
        node.update(change);
        telemetryListener.run();
    }

    private void observeOutgoing(Link link, byte[] bytes) {
        FrameReader r = new FrameReader();
        r.feed(bytes, 0, bytes.length, f -> observers.forEach(o -> o.frame(false, link, f)));
    }

    private void log(byte[] frame) {
        if (tlog != null) {
            try {
                tlog.write(frame);
            } catch (IOException e) {
                LOG.warn("tlog write failed: {}", e.getMessage());
            }
        }
    }

    /** Stops the thread, closes every socket and the tlog. */
    @Override
    public void close() {
        running = false;
        if (thread != null) {
            thread.interrupt();
            try {
                thread.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        closeLinks();
        if (tlog != null) {
            try {
                tlog.close();
            } catch (IOException e) {
                LOG.warn("closing the tlog failed: {}", e.getMessage());
            }
        }
    }

    private void closeLinks() {
        for (Link l : links) {
            try {
                l.close();
            } catch (IOException e) {
                LOG.warn("closing {} failed: {}", l, e.getMessage());
            }
        }
    }
}
