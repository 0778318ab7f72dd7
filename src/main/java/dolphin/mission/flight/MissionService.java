package dolphin.mission.flight;

import com.MAVLink.common.msg_mission_current;
import com.MAVLink.common.msg_mission_item_reached;
import com.MAVLink.common.msg_statustext;
import dolphin.core.Node;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mavlink.MessageHandler;
import dolphin.mission.transfer.MissionTransferConfig;
import dolphin.mission.transfer.MissionTransfers;
import dolphin.mavlink.ProtocolTimers;
import java.time.Duration;
import java.util.Map;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import dolphin.mission.transfer.TransferResult;
import dolphin.mission.transfer.TransferStatus;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

/**
 * The mission layer on one {@link MAVLinkCommunications}: it registers for the mission protocol's
 * messages and MISSION_ITEM_REACHED, and keeps each vehicle's {@link VehicleMissions} (transfers and
 * the executor flying on it) and how transfers and flights are configured. The link layer knows
 * nothing of it: it is attached as an extension of the communications on first use.
 */
public final class MissionService {

    private final MAVLinkCommunications comms;
    private final Map<MAVLinkNode, VehicleMissions> vehicles = new ConcurrentHashMap<>();
    private final ProtocolTimers timers;
    private volatile MissionTransferConfig transferConfig = MissionTransferConfig.DEFAULT;
    private volatile MissionExecutorConfig executorConfig = MissionExecutorConfig.DEFAULT;
    private final List<TransferListener> transferListeners = new CopyOnWriteArrayList<>();

    private MissionService(MAVLinkCommunications comms) {
        this.comms = comms;
        this.timers = new ProtocolTimers() {
            @Override
            public void execute(Runnable action) {
                comms.execute(action);
            }

            @Override
            public void schedule(Duration delay, Runnable action) {
                comms.schedule(delay, action);
            }

            @Override
            public long nanoTime() {
                return comms.clock().nanoTime();
            }
        };
        route(comms.messageHandler());
    }

    /** The mission layer of these communications, attached on first use. */
    public static MissionService of(MAVLinkCommunications comms) {
        return comms.extension(MissionService.class, MissionService::new);
    }

    /** The missions of a MAVLink vehicle; null for a vehicle of another platform. */
    public static MissionVehicle vehicleOf(Node node) {
        return node instanceof MAVLinkNode n ? of(n.communications()).vehicle(n) : null;
    }

    public VehicleMissions vehicle(MAVLinkNode node) {
        return vehicles.computeIfAbsent(node, n -> new VehicleMissions(n, this));
    }

    /** The executor flying a mission on the vehicle, or null; a vehicle never given a mission gets nothing made for it. */
    public MissionExecutor executorOn(MAVLinkNode node) {
        VehicleMissions v = vehicles.get(node);
        return v == null ? null : v.executor();
    }

    /** How mission uploads and downloads started from now on time their resends, give up and travel. */
    public MissionTransferConfig transferConfig() {
        return transferConfig;
    }

    public void setTransferConfig(MissionTransferConfig config) {
        transferConfig = Objects.requireNonNull(config, "config");
    }

    /** From now on, hears the progress and the end of every transfer the runtime makes; from any thread. */
    public void addTransferListener(TransferListener listener) {
        transferListeners.add(Objects.requireNonNull(listener, "listener"));
    }

    public void removeTransferListener(TransferListener listener) {
        transferListeners.remove(listener);
    }

    /** Where the vehicle's transfer in progress stands; empty when none is, or for a vehicle we never transferred to. */
    public Optional<TransferStatus> transferOn(MAVLinkNode node) {
        VehicleMissions v = vehicles.get(node);
        return v == null ? Optional.empty() : v.transfer();
    }

    void transferred(String vehicleId, TransferStatus status) {
        transferListeners.forEach(l -> l.progress(vehicleId, status));
    }

    void transferEnded(String vehicleId, TransferResult result) {
        transferListeners.forEach(l -> l.ended(vehicleId, result));
    }

    /** How missions started from now on are flown. */
    public MissionExecutorConfig executorConfig() {
        return executorConfig;
    }

    public void setExecutorConfig(MissionExecutorConfig config) {
        executorConfig = Objects.requireNonNull(config, "config");
    }

    ProtocolTimers timers() {
        return timers;
    }

    private void route(MessageHandler handler) {
        // a vehicle we never gave a transfer or a mission has nothing of ours to hear them
        MissionTransfers.MESSAGES.forEach(type -> handler.on(type, (n, m) -> {
            VehicleMissions v = vehicles.get(n);
            if (v != null) {
                v.transfers().handle(m);
            }
        }));
        handler.on(msg_mission_item_reached.class, (n, m) -> toExecutor(n, e -> {
            e.consume(m);
            comms.wakeScript();
        }));
        // In the order they come, for the refused-item rule (ItemRefusals): snapshots miss a mission raced through.
        handler.on(msg_mission_current.class, (n, m) -> toExecutor(n, e -> e.consume(m)));
        handler.on(msg_statustext.class, (n, m) -> toExecutor(n, e -> e.consume(m)));
    }

    /** Hands a message to the executor flying on the vehicle, if one is. */
    private void toExecutor(MAVLinkNode node, Consumer<MissionExecutor> deliver) {
        MissionExecutor executor = executorOn(node);
        if (executor != null) {
            deliver.accept(executor);
        }
    }
}
