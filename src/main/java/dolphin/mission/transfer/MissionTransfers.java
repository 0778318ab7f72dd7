package dolphin.mission.transfer;

import dolphin.mavlink.ProtocolTimers;
import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_ack;
import com.MAVLink.common.msg_mission_count;
import com.MAVLink.common.msg_mission_item;
import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.common.msg_mission_request;
import com.MAVLink.common.msg_mission_request_int;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.function.Supplier;

/**
 * A vehicle's mission transfers: its {@link MissionUploadProtocol} and {@link MissionDownloadProtocol}
 * and the queue that runs their transfers one at a time (ArduPilot answers DENIED to a download
 * during an upload, and a second upload restarts the first). Everything but {@link #submit} runs on
 * the protocol's thread ({@link ProtocolTimers}). The mission layer feeds it the vehicle's mission
 * messages through {@link #handle}.
 */
public final class MissionTransfers {

    /** The vehicle's messages of the mission protocol, the ones {@link #handle} takes. */
    public static final List<Class<? extends MAVLinkMessage>> MESSAGES = List.of(msg_mission_request.class,
            msg_mission_request_int.class, msg_mission_ack.class, msg_mission_count.class, msg_mission_item_int.class,
            msg_mission_item.class);

    private final VehicleChannel vehicle;
    private final ProtocolTimers timers;
    private final Supplier<MissionTransferConfig> config;
    private final MissionUploadProtocol upload;
    private final MissionDownloadProtocol download;
    private final Deque<Transfer> waiting = new ArrayDeque<>();
    private Transfer active;

    /** @param config the timeouts and path of transfers started from now on (a command line may change them) */
    public MissionTransfers(VehicleChannel vehicle, ProtocolTimers timers, Supplier<MissionTransferConfig> config) {
        this.vehicle = vehicle;
        this.timers = timers;
        this.config = config;
        this.upload = new MissionUploadProtocol(this);
        this.download = new MissionDownloadProtocol(this);
    }

    public MissionUploadProtocol upload() {
        return upload;
    }

    public MissionDownloadProtocol download() {
        return download;
    }

    VehicleChannel vehicle() {
        return vehicle;
    }

    ProtocolTimers timers() {
        return timers;
    }

    MissionTransferConfig config() {
        return config.get();
    }

    /** Queues a transfer; from any thread. */
    void submit(Transfer transfer) {
        timers.execute(() -> {
            waiting.add(transfer);
            pump();
        });
    }

    private void pump() {
        if (active == null && !waiting.isEmpty()) {
            Transfer t = waiting.poll();
            active = t;
            t.begin(() -> {
                if (active == t) {
                    active = null;
                    timers.execute(this::pump);
                }
            });
        }
    }

    /**
     * A mission protocol message from the vehicle (MISSION_REQUEST, _INT, MISSION_ACK, MISSION_COUNT,
     * MISSION_ITEM_INT, MISSION_ITEM), on the protocol's thread; the others are ignored.
     */
    public void handle(MAVLinkMessage message) {
        if (message instanceof msg_mission_request m) {
            handle(message, m.target_system, m.mission_type);
        } else if (message instanceof msg_mission_request_int m) {
            handle(message, m.target_system, m.mission_type);
        } else if (message instanceof msg_mission_ack m) {
            handle(message, m.target_system, m.mission_type);
        } else if (message instanceof msg_mission_count m) {
            handle(message, m.target_system, m.mission_type);
        } else if (message instanceof msg_mission_item_int m) {
            handle(message, m.target_system, m.mission_type);
        } else if (message instanceof msg_mission_item m) {
            handle(message, m.target_system, m.mission_type);
        }
    }

    private void handle(MAVLinkMessage message, int targetSystem, int missionType) {
        // messages for another ground station, or of another list than the transfer's, are not ours
        if (active == null || missionType != active.type.wire()
                || (targetSystem != 0 && targetSystem != vehicle.groundSystem())) {
            return;
        }
        active.handle(message);
    }
}
