package dolphin.mission.transfer;

import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkNode;
import java.util.concurrent.CompletableFuture;

/**
 * One upload or download to one vehicle: a state machine that lives on the communications thread
 * (started, fed messages and timed out there only), with one clock-time timer at a time.
 */
abstract class MissionTransfer {

    final MAVLinkCommunications comms;
    final MAVLinkNode node;
    final MissionTransferConfig config;
    final TransferProgress progress;
    final MissionType type;
    final CompletableFuture<TransferResult> result = new CompletableFuture<>();
    int resends;
    int ignoredAcks;
    private int timerGeneration;
    private Runnable onDone = () -> { };

    MissionTransfer(MAVLinkCommunications comms, MAVLinkNode node, MissionTransferConfig config, TransferProgress progress,
                    MissionType type) {
        this.comms = comms;
        this.type = type;
        this.node = node;
        this.config = config;
        this.progress = progress == null ? TransferProgress.NONE : progress;
    }

    /** "upload to" or "download from", for messages. */
    abstract String what();

    /** Sends the first message. */
    abstract void start();

    /** A mission message from the vehicle (already checked to be for us and of this transfer's mission type). */
    abstract void handle(MAVLinkMessage message);

    final void begin(Runnable whenDone) {
        onDone = whenDone;
        start();
    }

    final boolean done() {
        return result.isDone();
    }

    final void send(MAVLinkMessage message) {
        comms.send(node, message);
    }

    /** Runs {@code action} after the timeout unless the transfer ends or another timer is armed first. */
    final void arm(Runnable action) {
        int generation = ++timerGeneration;
        comms.schedule(config.timeout(), () -> {
            if (!done() && generation == timerGeneration) {
                action.run();
            }
        });
    }

    final void succeed(java.util.List<MissionItem> items) {
        finish(TransferResult.ok(items, resends, ignoredAcks));
    }

    final void fail(String reason) {
        String lost = node.isConnected() ? "" : " (vehicle " + node.getId() + " is lost: no heartbeat within "
                + node.getConnectionTimeout() + " s)";
        String of = type == MissionType.MISSION ? "" : " of the " + type.label();
        String[] w = what().split(" ", 2);
        finish(TransferResult.failed(w[0] + of + " " + w[1] + " vehicle " + node.getId() + " failed: " + reason + lost,
                resends, ignoredAcks));
    }

    private void finish(TransferResult r) {
        if (done()) {
            return;
        }
        timerGeneration++;
        result.complete(r);
        onDone.run();
    }

    final int gcsSysid() {
        return comms.config().sysid();
    }

    final int tries() {
        return config.tries();
    }

    /** "5 MISSION_COUNTs (1.5 s apart)". */
    final String sent(int times, String message) {
        return times + " " + message + (times == 1 ? "" : "s") + (times > 1 ? " (" + config.timeoutText() + " apart)" : "");
    }
}
