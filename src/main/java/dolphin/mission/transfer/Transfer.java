package dolphin.mission.transfer;

import dolphin.mavlink.ProtocolTimers;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import com.MAVLink.Messages.MAVLinkMessage;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * One upload or download to one vehicle: a state machine that lives on the communications thread
 * (started, fed messages and timed out there only), with one clock-time timer at a time. Its
 * timeouts follow the link's measured round trip, doubled per timeout in a row without progress
 * (twice at most, {@link dolphin.mavlink.LinkTimeouts#MOST_BACKOFFS});
 * it gives up after {@code config.timeouts().giveUp()} of clock time without progress
 * (docs/decisions.md, "Transfers on lossy links").
 */
abstract class Transfer {

    final VehicleChannel vehicle;
    final ProtocolTimers timers;
    final MissionTransferConfig config;
    final TransferProgress progress;
    final MissionType type;
    final CompletableFuture<TransferResult> result = new CompletableFuture<>();
    int resends;
    /** The vehicle's id of the list, from its MISSION_ACK or MISSION_COUNT (TransferResult.planId). */
    long planId;
    int ignoredAcks;
    private int timerGeneration;
    private int backoffs;           // timeouts in a row without progress
    private long progressAt;        // clock time of the last progress
    private String reason = "";
    private String fallback = "";
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
        progressAt = timers.nanoTime();
        start();
    }

    final boolean done() {
        return result.isDone();
    }

    final void send(MAVLinkMessage message) {
        vehicle.send(message);
    }

    /** The vehicle answered something new: the timeout forgets its back-off and the patience starts again. */
    final void advanced() {
        backoffs = 0;
        progressAt = timers.nanoTime();
    }

    /** A timeout passed without progress: the next one is twice as long (up to the maximum). */
    final void backOff() {
        backoffs++;
    }

    /** The retransmission timeout now: the link's, backed off by the timeouts in a row. */
    final Duration timeout() {
        return config.timeouts().timeout(vehicle.roundTrip(), backoffs);
    }

    /** Whether the transfer may still wait: less than the give-up time passed since the last progress. */
    final boolean patient() {
        return timers.nanoTime() - progressAt < config.timeouts().giveUp().toNanos();
    }

    /** A clean round-trip sample (the answer to a message sent once, Karn's rule): sent at {@code sentAt}, answered now. */
    final void sample(long sentAt) {
        vehicle.roundTrip().sample(timers.nanoTime() - sentAt);
    }

    /** Runs {@code action} after the timeout unless the transfer ends or another timer is armed first. */
    final void arm(Runnable action) {
        arm(timeout(), action);
    }

    /** The same after {@code delay}, but never later than the moment the transfer would give up. */
    final void arm(Duration delay, Runnable action) {
        int generation = ++timerGeneration;
        long left = progressAt + config.timeouts().giveUp().toNanos() - timers.nanoTime();
        timers.schedule(Duration.ofNanos(Math.max(0, Math.min(delay.toNanos(), left))), () -> {
            if (!done() && generation == timerGeneration) {
                action.run();
            }
        });
    }

    /** No timer runs until the next {@link #arm}. */
    final void disarm() {
        timerGeneration++;
    }

    final void succeed(List<MissionItem> items) {
        finish(TransferResult.ok(items, resends, ignoredAcks).withPlanId(planId));
    }

    /** An upload that read its list back and found it equal, with how it went. */
    final void succeedVerified(List<MissionItem> items, String note) {
        finish(TransferResult.verified(items, resends, ignoredAcks, note).withPlanId(planId));
    }

    final void fail(String reason) {
        this.reason = reason;
        String silence = vehicle.silence();
        String lost = silence.isEmpty() ? "" : " (vehicle " + vehicle.vehicleId() + " is lost: " + silence + ")";
        String of = type == MissionType.MISSION ? "" : " of the " + type.label();
        String[] w = what().split(" ", 2);
        finish(TransferResult.failed(w[0] + of + " " + w[1] + " vehicle " + vehicle.vehicleId() + " failed: " + reason + lost,
                resends, ignoredAcks));
    }

    /**
     * Why the transfer took its path, when it was not the one asked for or the one a user would
     * expect (it stands in for one that failed over FTP, or the vehicle did not offer FTP): its
     * result says so first.
     */
    final void pathNote(String why) {
        fallback = why;
    }

    /** Why the transfer failed, as passed to {@link #fail} (empty unless it failed). */
    final String reason() {
        return reason;
    }

    private void finish(TransferResult r) {
        if (done()) {
            return;
        }
        timerGeneration++;
        result.complete(fallback.isEmpty() ? r : r.notedFirst(fallback));
        onDone.run();
    }

    /** Reports progress over the mission protocol: {@code done} of {@code total} items (-1 while unknown). */
    final void report(long done, long total) {
        progress.progress(new TransferStatus(type, what().startsWith("upload"), TransferPath.ITEMS, done, total, resends));
    }

    /** "no MISSION_COUNT in 10 s (MISSION_REQUEST_LIST sent 7 times)". */
    final String waited(String awaited, String message, int times) {
        return "no " + awaited + " in " + seconds(config.timeouts().giveUp()) + " (" + message + " sent " + times
                + (times == 1 ? " time)" : " times)");
    }

    /** "10 s", "2.5 s". */
    static String seconds(Duration d) {
        return java.math.BigDecimal.valueOf(d.toMillis(), 3).stripTrailingZeros().toPlainString() + " s";
    }
}
