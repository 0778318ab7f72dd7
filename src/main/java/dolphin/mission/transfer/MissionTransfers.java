package dolphin.mission.transfer;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_ack;
import com.MAVLink.common.msg_mission_count;
import com.MAVLink.common.msg_mission_item;
import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.common.msg_mission_request;
import com.MAVLink.common.msg_mission_request_int;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mavlink.MessageHandler;
import java.util.ArrayDeque;
import java.util.Deque;

/**
 * A vehicle's mission transfers: its {@link MissionUploadProtocol} and {@link MissionDownloadProtocol}
 * and the queue that runs their transfers one at a time (ArduPilot answers DENIED to a download
 * during an upload, and a second upload restarts the first). Everything but {@link #submit} runs on
 * the communications thread.
 */
public final class MissionTransfers {

    private final MAVLinkCommunications comms;
    private final MAVLinkNode node;
    private final MissionUploadProtocol upload;
    private final MissionDownloadProtocol download;
    private final Deque<MissionTransfer> waiting = new ArrayDeque<>();
    private MissionTransfer active;

    public MissionTransfers(MAVLinkCommunications comms, MAVLinkNode node) {
        this.comms = comms;
        this.node = node;
        this.upload = new MissionUploadProtocol(comms, node, this);
        this.download = new MissionDownloadProtocol(comms, node, this);
    }

    public MissionUploadProtocol upload() {
        return upload;
    }

    public MissionDownloadProtocol download() {
        return download;
    }

    /** Routes the vehicles' mission messages to their nodes' transfers; called once by the communications. */
    public static void route(MessageHandler handler) {
        handler.on(msg_mission_request.class, (n, m) -> n.missionTransfers().handle(m, m.target_system, m.mission_type));
        handler.on(msg_mission_request_int.class, (n, m) -> n.missionTransfers().handle(m, m.target_system, m.mission_type));
        handler.on(msg_mission_ack.class, (n, m) -> n.missionTransfers().handle(m, m.target_system, m.mission_type));
        handler.on(msg_mission_count.class, (n, m) -> n.missionTransfers().handle(m, m.target_system, m.mission_type));
        handler.on(msg_mission_item_int.class, (n, m) -> n.missionTransfers().handle(m, m.target_system, m.mission_type));
        handler.on(msg_mission_item.class, (n, m) -> n.missionTransfers().handle(m, m.target_system, m.mission_type));
    }

    /** Queues a transfer; from any thread. */
    void submit(MissionTransfer transfer) {
        comms.execute(() -> {
            waiting.add(transfer);
            pump();
        });
    }

    /** True while a transfer runs or waits; communications thread only. */
    boolean busy() {
        return active != null || !waiting.isEmpty();
    }

    private void pump() {
        if (active == null && !waiting.isEmpty()) {
            MissionTransfer t = waiting.poll();
            active = t;
            t.begin(() -> {
                if (active == t) {
                    active = null;
                    comms.execute(this::pump);
                }
            });
        }
    }

    private void handle(MAVLinkMessage message, int targetSystem, int missionType) {
        // messages for another ground station, or of another list than the transfer's, are not ours
        if (active == null || missionType != active.type.wire()
                || (targetSystem != 0 && targetSystem != comms.config().sysid())) {
            return;
        }
        active.handle(message);
    }
}
