package dolphin.mission.transfer;

import dolphin.mavlink.ProtocolTimers;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import com.MAVLink.Messages.MAVLinkMessage;
import java.util.concurrent.CompletableFuture;

/**
 * One upload or download to one vehicle: a state machine that lives on the communications thread
 * (started, fed messages and timed out there only), with one clock-time timer at a time.
 */
abstract class Transfer {

    final VehicleChannel vehicle;
    final ProtocolTimers timers;
    final MissionTransferConfig config;
    final TransferProgress progress;
    final MissionType type;
    final CompletableFuture<TransferResult> result = new CompletableFuture<>();
    int resends;
    int ignoredAcks;
    private int timerGeneration;
    private Runnable onDone = () -> { };

    Transfer(VehicleChannel vehicle, ProtocolTimers timers, MissionTransferConfig config, TransferProgress progress,
             MissionType type) {
        this.vehicle = vehicle;
        this.timers = timers;
        this.type = type;
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
        vehicle.send(message);
    }

    /** Runs {@code action} after the timeout unless the transfer ends or another timer is armed first. */
    final void arm(Runnable action) {
        int generation = ++timerGeneration;
        timers.schedule(config.timeout(), () -> {
            if (!done() && generation == timerGeneration) {
                action.run();
            }
        });
    }

    final void succeed(java.util.List<MissionItem> items) {
        finish(TransferResult.ok(items, resends, ignoredAcks));
    }

    final void fail(String reason) {
        String silence = vehicle.silence();
        String lost = silence.isEmpty() ? "" : " (vehicle " + vehicle.vehicleId() + " is lost: " + silence + ")";
        String of = type == MissionType.MISSION ? "" : " of the " + type.label();
        String[] w = what().split(" ", 2);
        finish(TransferResult.failed(w[0] + of + " " + w[1] + " vehicle " + vehicle.vehicleId() + " failed: " + reason + lost,
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

    /** Reports progress over the mission protocol: {@code done} of {@code total} items (-1 while unknown). */
    final void report(long done, long total) {
        progress.progress(new TransferStatus(type, what().startsWith("upload"), TransferPath.ITEMS, done, total, resends));
    }

    final int tries() {
        return config.tries();
    }

    /** "5 MISSION_COUNTs (1.5 s apart)". */
    final String sent(int times, String message) {
        return times + " " + message + (times == 1 ? "" : "s") + (times > 1 ? " (" + config.timeoutText() + " apart)" : "");
    }
}
