package dolphin.mission.flight;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_home_position;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_PROTOCOL_CAPABILITY;
import dolphin.core.Position;
import dolphin.core.VehicleEvent;
import dolphin.core.VehicleEvent.EventKind;
import dolphin.mavlink.CommandResult;
import dolphin.mavlink.LinkHealth;
import dolphin.mavlink.LinkRequests;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mavlink.RoundTrip;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.VehicleFamily;
import dolphin.mavlink.VehicleState;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.transfer.MissionTransfers;
import dolphin.mission.transfer.TransferResult;
import dolphin.mission.transfer.TransferStatus;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

/**
 * One MAVLink vehicle's missions: its transfers and the executor flying on it, kept by
 * {@link MissionService}; the vehicle as the transfers and the executor see it.
 */
public final class VehicleMissions implements MissionVehicle {

    private final MAVLinkNode node;
    private final MissionService service;
    private final MissionTransfers transfers;
    private final AtomicReference<MissionExecutor> executor = new AtomicReference<>();
    /** The latest progress of a transfer in progress, null when none is. */
    private volatile TransferStatus transfer;
    /** Whether a mission of ours on the vehicle is paused by someone else's hand now, and how often that began. */
    private volatile boolean takenOver;
    private final AtomicInteger takeovers = new AtomicInteger();

    VehicleMissions(MAVLinkNode node, MissionService service) {
        this.node = node;
        this.service = service;
        this.transfers = new MissionTransfers(this, service.timers(), service::transferConfig);
    }

    /** The vehicle's uploads and downloads, one at a time. */
    public MissionTransfers transfers() {
        return transfers;
    }

    /** The executor flying a mission on the vehicle, or null. */
    public MissionExecutor executor() {
        return executor.get();
    }

    @Override
    public void flying(MissionExecutor e) {
        executor.set(e);
    }

    @Override
    public void landed(MissionExecutor e) {
        if (executor.compareAndSet(e, null)) {
            takenOver = false;
        }
    }

    /** Publishes the event to the communications' listeners, and keeps count of takeovers for the script's words. */
    @Override
    public void event(EventKind kind, String text) {
        if (kind == EventKind.TAKEN_OVER) {
            takeovers.incrementAndGet();
            takenOver = true;
        } else if (kind == EventKind.HANDED_BACK) {
            takenOver = false;
        }
        var comms = node.communications();
        comms.publish(new VehicleEvent(node.getId(), kind, text, comms.clock().seconds()));
    }

    /** Whether a mission of ours on the vehicle is paused now by someone else's hand (docs/failures.md). */
    public boolean takenOver() {
        return takenOver;
    }

    /** How many times someone else took the vehicle out of AUTO while a mission of ours flew on it. */
    public int takeovers() {
        return takeovers.get();
    }

    @Override
    public String vehicleId() {
        return node.getId();
    }

    @Override
    public int system() {
        return node.getMavLinkId();
    }

    @Override
    public int component() {
        return node.getAutopilotCompid();
    }

    @Override
    public VehicleState state() {
        return node.state();
    }

    @Override
    public CompletableFuture<CommandResult> command(int command, float... params) {
        return node.communications().command(node, command, params);
    }

    @Override
    public CompletableFuture<OptionalDouble> parameter(String name) {
        return node.communications().parameter(node, name);
    }

    @Override
    public void send(MAVLinkMessage message) {
        node.send(message);
    }

    @Override
    public CompletableFuture<TransferResult> upload(MissionType type, List<MissionItem> items) {
        return watched(transfers.upload().upload(type, items, service.transferConfig(), this::transferred));
    }

    @Override
    public CompletableFuture<TransferResult> download(MissionType type) {
        return watched(transfers.download().download(type, service.transferConfig(), this::transferred));
    }

    @Override
    public Optional<TransferStatus> transfer() {
        return Optional.ofNullable(transfer);
    }

    private void transferred(TransferStatus status) {
        transfer = status;
        service.transferred(vehicleId(), status);
    }

    private CompletableFuture<TransferResult> watched(CompletableFuture<TransferResult> result) {
        return result.whenComplete((r, e) -> {
            transfer = null;
            if (r != null) {
                service.transferEnded(vehicleId(), r);
            }
        });
    }

    @Override
    public int groundSystem() {
        return node.communications().config().sysid();
    }

    @Override
    public RoundTrip roundTrip() {
        return node.roundTrip();
    }

    @Override
    public Optional<Boolean> offersFtp() {
        var bits = node.capabilities();
        return bits.isPresent() ? Optional.of((bits.getAsLong() & MAV_PROTOCOL_CAPABILITY.MAV_PROTOCOL_CAPABILITY_FTP) != 0)
                : Optional.empty();
    }

    @Override
    public boolean throughRadio() {
        return node.throughRadio();
    }

    @Override
    public LinkRequests linkRequests() {
        return node.linkRequests();
    }

    @Override
    public int radioBufferFree() {
        LinkHealth health = node.linkHealth();
        return health.radioCurrent() ? health.radio().txbuf() : -1;
    }

    @Override
    public Position home() {
        return node.getHome();
    }

    @Override
    public void askHome() {
        node.communications().command(node, MAV_CMD.MAV_CMD_REQUEST_MESSAGE, msg_home_position.MAVLINK_MSG_ID_HOME_POSITION);
    }

    @Override
    public Autopilot autopilot() {
        return node.state().autopilot();
    }

    @Override
    public VehicleFamily family() {
        return node.getFamily();
    }

    @Override
    public void askWhatItOffers() {
        node.askCapabilities();
    }

    @Override
    public int unansweredAsks() {
        return node.capabilityAsks();
    }

    @Override
    public String silence() {
        return node.isConnected() ? "" : "no heartbeat within " + node.getConnectionTimeout() + " s";
    }

    @Override
    public MissionExecutorConfig executorConfig() {
        return service.executorConfig();
    }

    @Override
    public void wake() {
        node.communications().wakeScript();
    }
}
