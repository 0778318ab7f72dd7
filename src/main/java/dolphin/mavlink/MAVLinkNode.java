package dolphin.mavlink;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.AbstractNode;
import dolphin.core.Clock;
import dolphin.core.EnvironmentException;
import dolphin.core.Payload;
import dolphin.core.Position;
import dolphin.mavlink.link.Link;
import dolphin.mavlink.link.LinkUrl;
import java.net.SocketAddress;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;
import java.util.function.UnaryOperator;

/**
 * A MAVLink vehicle as a Dolphin node: a system id on a link, or on several when they bring the same
 * frames ({@link VehicleLinks}). Its state is an immutable {@link VehicleState} that the
 * communications thread replaces and any thread reads.
 */
public final class MAVLinkNode extends AbstractNode {

    /**
     * How long {@link #batteryRemaining()} and {@link #awaitPosition()} wait for the first SYS_STATUS
     * or GLOBAL_POSITION_INT of a vehicle just discovered (docs/decisions.md, "Engine semantics").
     */
    public static final Duration TELEMETRY_WAIT = Duration.ofSeconds(5);

    private final MAVLinkCommunications comms;
    private final VehicleLinks links;
    private final int sysid;
    private final int autopilotCompid;
    private final Clock clock;
    private final AtomicReference<VehicleState> state;
    private final RoundTrip roundTrip = new RoundTrip();
    private final Contact contact;
    /** AUTOPILOT_VERSION.capabilities (MAV_PROTOCOL_CAPABILITY bits), -1 until the vehicle sent it. */
    private volatile long capabilities = -1;
    /** AUTOPILOT_VERSION requests sent since the last answer; written on the communications thread only. */
    private volatile int capabilityAsks;
    /** What a fleet file says of the vehicle, when it says it (docs/sensors.md, "Fleet files"). */
    private volatile String name;
    private volatile String declaredType;
    /** The connection state the communications thread last reported; only it reads and writes this. */
    boolean wasConnected = true;

    MAVLinkNode(String id, String type, MAVLinkCommunications comms, Link link, SocketAddress address, int sysid,
                int autopilotCompid, Autopilot autopilot, VehicleFamily family, Clock clock) {
        super(id, type, Payload.NONE);
        this.comms = comms;
        this.links = new VehicleLinks(link, address, clock.nanoTime());
        this.sysid = sysid;
        this.autopilotCompid = autopilotCompid;
        this.clock = clock;
        this.state = new AtomicReference<>(VehicleState.initial(autopilot, family));
        this.contact = new Contact(id, clock);
    }

    /** The MAVLink system id (getMavLinkId in the original). */
    public int getMavLinkId() {
        return sysid;
    }

    public MAVLinkCommunications communications() {
        return comms;
    }

    public int getAutopilotCompid() {
        return autopilotCompid;
    }

    /** The MAV_PROTOCOL_CAPABILITY bits of the vehicle's AUTOPILOT_VERSION, asked for at discovery; empty until it answers. */
    public java.util.OptionalLong capabilities() {
        long c = capabilities;
        return c < 0 ? java.util.OptionalLong.empty() : java.util.OptionalLong.of(c);
    }

    void capabilities(long bits) {
        capabilities = bits;
        capabilityAsks = 0;
    }

    /**
     * How many times the vehicle was asked what it offers since it last answered (0 once it did): a
     * transfer that cannot wait says how long it was left without an answer.
     */
    public int capabilityAsks() {
        return capabilityAsks;
    }

    void capabilityAsked() {
        capabilityAsks++;
    }

    /**
     * Asks the vehicle again what it offers, unless it answered or an ask is on its way: for a
     * transfer that would choose its path by the answer. From any thread.
     */
    public void askCapabilities() {
        comms.execute(() -> comms.hurryCapabilities(this));
    }

    /** The measured round trip of the vehicle's link (command ACKs, mission transfers, FTP). */
    public RoundTrip roundTrip() {
        return roundTrip;
    }

    /** The link the vehicle's sends go through: of its links, the one chosen by {@link VehicleLinks}. */
    public Link getLink() {
        return links.path().link();
    }

    /**
     * Whether the vehicle is reached through a telemetry radio: its link is a serial port (where
     * radios sit), or a radio reports on it. Transfers then send frames a SiK radio carries well
     * (docs/radios.md).
     */
    public boolean throughRadio() {
        Link link = getLink();
        // asked for each FTP request: whether a radio reported, not the link's whole health
        return link != null && (link.url().kind() == LinkUrl.Transport.SERIAL || comms.radioHeard(link));
    }

    /** The requests in flight on the link the vehicle is reached through, shared with the other vehicles on it. */
    public LinkRequests linkRequests() {
        return comms.linkRequests(getLink());
    }

    /**
     * The health of the link the vehicle is reached through, now: its traffic each way and the latest
     * report of a telemetry radio on it (docs/embedding.md, "Link health"). From any thread.
     */
    public LinkHealth linkHealth() {
        return comms.linkHealth(getLink());
    }

    /** Where the vehicle was last heard on that link: replies go there. */
    public SocketAddress getAddress() {
        return links.path().address();
    }

    /** Every link the vehicle is heard on, the one it was discovered on first. */
    public List<Link> getLinks() {
        return links.all().stream().map(VehicleLinks.Traffic::link).toList();
    }

    /** Frames of the vehicle that {@code link} brought after another of its links had: dropped. */
    public long duplicatesOn(Link link) {
        return links.all().stream().filter(t -> t.link() == link).mapToLong(VehicleLinks.Traffic::duplicates).sum();
    }

    /** For the communications thread. */
    VehicleLinks links() {
        return links;
    }

    /** The fleet file's name for the vehicle, else its id. */
    @Override
    public String getName() {
        String n = name;
        return n == null ? getId() : n;
    }

    /** The fleet file's Dolphin type for the vehicle, else the one its heartbeat's MAV_TYPE gives. */
    @Override
    public String getType() {
        String t = declaredType;
        return t == null ? super.getType() : t;
    }

    /** What a fleet file says of the vehicle: its name and Dolphin type, each null to keep what it is. */
    public void declare(String fleetName, String fleetType) {
        if (fleetName != null) {
            name = fleetName;
        }
        if (fleetType != null) {
            declaredType = fleetType;
        }
    }

    public VehicleFamily getFamily() {
        return state.get().family();
    }

    /** The current snapshot of everything known about the vehicle. */
    public VehicleState state() {
        return state.get();
    }

    void update(UnaryOperator<VehicleState> change) {
        state.updateAndGet(change);
    }

    @Override
    public Position getPosition() {
        return state.get().position();
    }

    public String getModeName() {
        return state.get().modeName();
    }

    public boolean isArmed() {
        return state.get().armed();
    }

    public Position getHome() {
        return state.get().home();
    }

    /** Whether the vehicle is heard, for the communications thread. */
    Contact contact() {
        return contact;
    }

    /**
     * How long the vehicle has been silent, while it is: nothing from its autopilot for 3 s or more
     * (docs/decisions.md, "Contact"). Empty while it is heard. A silent vehicle is still connected
     * until its connection timeout.
     */
    public Optional<Duration> silence() {
        return contact.silence();
    }

    /** Heard within the connection timeout (docs/decisions.md, "The link"). */
    @Override
    public boolean isConnected() {
        long last = state.get().heartbeatNanos();
        return clock.nanoTime() - last <= (long) (getConnectionTimeout() * 1e9);
    }

    /**
     * The battery as a fraction: waits up to 5 s for a SYS_STATUS with a level, then fails with a clear
     * error. A level of -1 is waited out too: ArduPilot reports it for its first seconds after boot,
     * before its battery monitor has read the battery, and for good without a monitor. Never a made-up
     * value: Groovy orders NaN above every number, so a NaN would silently satisfy {@code >=}
     * (docs/decisions.md, "Engine semantics").
     */
    @Override
    public double batteryRemaining() {
        if (!awaitTelemetry("battery", s -> s.systemStatus() != null && s.batteryPercent() >= 0)) {
            if (state.get().systemStatus() == null) {
                throw new EnvironmentException("battery: vehicle " + getId() + " has sent no SYS_STATUS in "
                        + TELEMETRY_WAIT.toSeconds() + " s (are its telemetry streams reaching us?)");
            }
            throw new EnvironmentException("battery: vehicle " + getId() + " reports no battery level (battery_remaining -1"
                    + " for " + TELEMETRY_WAIT.toSeconds() + " s: no battery monitor configured)");
        }
        return state.get().batteryPercent() / 100.0;
    }

    /** The position, after waiting up to 5 s for the first GLOBAL_POSITION_INT; null if none came. */
    @Override
    public Position awaitPosition() {
        awaitTelemetry("position", s -> s.position() != null);
        return getPosition();
    }

    /** Waits on the clock until the state shows what a vehicle just discovered has not sent yet; false at the deadline. */
    private boolean awaitTelemetry(String what, Predicate<VehicleState> arrived) {
        return awaitWithin(what, () -> arrived.test(state.get()));
    }

    /**
     * Waits on the clock, up to {@link #TELEMETRY_WAIT}, until {@code arrived} holds: how the words that
     * read what a vehicle sends (battery, position, sensors) wait for its first report. False at the deadline.
     */
    public boolean awaitWithin(String what, BooleanSupplier arrived) {
        long deadline = clock.nanoTime() + TELEMETRY_WAIT.toNanos();
        while (!arrived.getAsBoolean()) {
            if (clock.nanoTime() >= deadline) {
                return false;
            }
            try {
                clock.sleep(Duration.ofMillis(50));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new EnvironmentException(what + ": interrupted while waiting for vehicle " + getId(), e);
            }
        }
        return true;
    }

    /** Sends a message to this vehicle, on the link and to the address it was heard at. */
    public void send(MAVLinkMessage message) {
        comms.send(this, message);
    }

    /** Nothing is sent: the script no longer tasks the vehicle; a mission flying on it goes on. */
    @Override
    public void release() {
    }

    @Override
    public String toString() {
        return getId();
    }
}
