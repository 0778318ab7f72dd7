package dolphin.mission.transfer;

import dolphin.mavlink.Autopilot;
import dolphin.mavlink.ProtocolTimers;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_ack;
import com.MAVLink.common.msg_mission_count;
import com.MAVLink.common.msg_mission_item;
import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.common.msg_mission_request_int;
import com.MAVLink.common.msg_mission_request_list;
import com.MAVLink.enums.MAV_FRAME;
import com.MAVLink.enums.MAV_MISSION_RESULT;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * Downloads a vehicle's mission (unlike the original's, it keeps the items and has timeouts and retries): MISSION_REQUEST_LIST
 * until MISSION_COUNT, then MISSION_REQUEST_INT for each seq, up to four outstanding, again on timeout, accepting
 * MISSION_ITEM_INT (or float MISSION_ITEM, converted), and the final MISSION_ACK ACCEPTED.
 * The result's items include item 0 (ArduPilot's home). Timeouts follow the link's round trip,
 * which answers to messages sent once feed; it gives up after a time without progress
 * (docs/decisions.md, "Transfers on lossy links").
 */
public final class MissionDownloadProtocol {

    private final MissionTransfers transfers;

    MissionDownloadProtocol(MissionTransfers transfers) {
        this.transfers = transfers;
    }

    /** Downloads the vehicle's mission; from any thread. */
    public CompletableFuture<TransferResult> download() {
        return download(transfers.config(), TransferProgress.NONE);
    }

    public CompletableFuture<TransferResult> download(MissionTransferConfig config, TransferProgress progress) {
        return download(MissionType.MISSION, config, progress);
    }

    /** Downloads the vehicle's fence, rally points or mission; from any thread. */
    public CompletableFuture<TransferResult> download(MissionType type) {
        return download(type, transfers.config(), TransferProgress.NONE);
    }

    public CompletableFuture<TransferResult> download(MissionType type, MissionTransferConfig config, TransferProgress progress) {
        Download d = new Download(transfers.vehicle(), transfers.timers(), config, progress, type);
        transfers.submit(d);
        VehicleChannel vehicle = transfers.vehicle();
        if (AutopilotLists.offset(vehicle.autopilot(), type) == 0) {
            return d.result;
        }
        return d.result.thenApply(r -> !r.success() ? r
                : r.withItems(AutopilotLists.fromVehicle(vehicle.autopilot(), type, r.items(), vehicle.home())));
    }

    /** A float MISSION_ITEM as an item: latitude and longitude to degE7 in global frames. */
    static MissionItem fromFloat(msg_mission_item m) {
        boolean global = switch (m.frame) {
            case MAV_FRAME.MAV_FRAME_GLOBAL, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT, MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT,
                 MAV_FRAME.MAV_FRAME_GLOBAL_INT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                 MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT -> true;
            default -> false;
        };
        int x = global ? MissionItem.degE7(m.x) : Math.round(m.x);
        int y = global ? MissionItem.degE7(m.y) : Math.round(m.y);
        return new MissionItem(m.seq, m.command, m.frame, m.param1, m.param2, m.param3, m.param4, x, y, m.z, m.autocontinue != 0);
    }

    /**
     * The state machine of one download; communications thread only; the upload uses it too, to
     * read its list back. Up to {@link #WINDOW} MISSION_REQUEST_INTs outstanding, lowest seqs first
     * (ArduPilot answers any request in range, in any order): items may come lost, twice or out of
     * order; each arrives once into its place, and each request unanswered for a timeout goes
     * again. From an autopilot that answers only the next request or the last again (PX4, which
     * aborts the transfer on any other), one at a time ({@link Autopilot#requestsAhead}).
     */
    static final class Download extends Transfer {
        /** Requests outstanding at most: hides most of the round trip, while a slow radio's queue stays short. */
        static final int WINDOW = 4;

        private final int window;
        private MissionItem[] got;
        private int[] sends;           // sends of each request
        private long[] sentAt;         // when each request was last sent
        private int count = -1;        // -1 until MISSION_COUNT
        private int received;
        private int next;              // the lowest seq never requested
        private int low;               // the lowest seq not received
        private int listSends;
        private long listAt;

        Download(VehicleChannel vehicle, ProtocolTimers timers, MissionTransferConfig config, TransferProgress progress,
                 MissionType type) {
            super(vehicle, timers, config, progress, type);
            window = vehicle.autopilot().requestsAhead() ? WINDOW : 1;
        }

        @Override
        String what() {
            return "download from";
        }

        @Override
        void start() {
            sendList();
        }

        private void sendList() {
            msg_mission_request_list m = new msg_mission_request_list();
            m.target_system = (short) vehicle.system();
            m.target_component = (short) vehicle.component();
            m.mission_type = (short) type.wire();
            listSends++;
            listAt = timers.nanoTime();
            send(m);
            arm(() -> {
                if (!patient()) {
                    fail(waited("MISSION_COUNT", "MISSION_REQUEST_LIST", listSends));
                } else {
                    backOff();
                    resends++;
                    sendList();
                }
            });
        }

        private void request(int seq) {
            msg_mission_request_int m = new msg_mission_request_int();
            m.target_system = (short) vehicle.system();
            m.target_component = (short) vehicle.component();
            m.seq = seq;
            m.mission_type = (short) type.wire();
            if (sends[seq] > 0) {
                resends++;
            }
            sends[seq]++;
            sentAt[seq] = timers.nanoTime();
            send(m);
        }

        /** Requests the next seqs while fewer than the window are outstanding, and times the oldest outstanding. */
        private void fill() {
            while (next < count && next - received < window) {
                request(next++);
            }
            long oldest = Long.MAX_VALUE;
            for (int seq = low; seq < next; seq++) {
                if (got[seq] == null) {
                    oldest = Math.min(oldest, sentAt[seq]);
                }
            }
            long left = oldest + timeout().toNanos() - timers.nanoTime();
            arm(java.time.Duration.ofNanos(Math.max(0, left)), this::timedOut);
        }

        private void timedOut() {
            if (!patient()) {
                fail(waited("item " + low + " of " + count, "MISSION_REQUEST_INT", sends[low]));
                return;
            }
            long due = timers.nanoTime() - timeout().toNanos();
            backOff();
            for (int seq = low; seq < next; seq++) {
                if (got[seq] == null && sentAt[seq] <= due) {
                    request(seq);
                }
            }
            fill();
        }

        @Override
        void handle(MAVLinkMessage message) {
            if (message instanceof msg_mission_count c) {
                if (count < 0) {            // a later COUNT answers a duplicated REQUEST_LIST: ignored
                    if (listSends == 1) {
                        sample(listAt);
                    }
                    advanced();
                    count = c.count;
                    planId = c.opaque_id;
                    got = new MissionItem[count];
                    sends = new int[count];
                    sentAt = new long[count];
                    report(0, count);
                    if (count == 0) {
                        finishDownload();
                    } else {
                        fill();
                    }
                }
            } else if (message instanceof msg_mission_item_int m) {
                item(MissionItem.fromMessage(m));
            } else if (message instanceof msg_mission_item m) {
                item(fromFloat(m));
            } else if (message instanceof msg_mission_ack a && (a.type == MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE
                    || a.type == MAV_MISSION_RESULT.MAV_MISSION_ERROR && count < 0)) {
                ignoredAcks++;              // a late ACK of a duplicated item from an earlier upload (ERROR once it ended), on a noisy link
            } else if (message instanceof msg_mission_ack a && a.type != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
                fail(MissionUploadProtocol.resultName(a.type) + (count < 0 ? " (answering MISSION_REQUEST_LIST)"
                        : " (answering the request for item " + low + " of " + count + ")"));
            }
        }

        private void item(MissionItem item) {
            int seq = item.seq();
            if (count < 0 || seq < 0 || seq >= next || got[seq] != null) {
                return;                     // a duplicate, or not asked for (late, from an earlier transfer)
            }
            if (sends[seq] == 1) {
                sample(sentAt[seq]);
            }
            advanced();
            got[seq] = item;
            received++;
            while (low < count && got[low] != null) {
                low++;
            }
            report(received, count);
            if (received == count) {
                finishDownload();
            } else {
                fill();
            }
        }

        private void finishDownload() {
            msg_mission_ack ack = new msg_mission_ack();
            ack.target_system = (short) vehicle.system();
            ack.target_component = (short) vehicle.component();
            ack.type = MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
            ack.mission_type = (short) type.wire();
            send(ack);
            succeed(got == null ? List.of() : List.of(got));
        }
    }
}
