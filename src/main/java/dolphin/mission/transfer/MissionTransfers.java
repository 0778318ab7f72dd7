package dolphin.mission.transfer;

import dolphin.mavlink.ProtocolTimers;
import dolphin.mavlink.RoundTrip;
import dolphin.mavlink.ftp.FtpChannel;
import dolphin.mavlink.ftp.FtpClient;
import dolphin.mission.model.MissionItem;
import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_file_transfer_protocol;
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
 *
 * <p>Each transfer takes the path its config asks for when its turn comes (docs/decisions.md,
 * "Transfers on lossy links"): ITEMS the mission protocol; FTP the whole list as one file over
 * MAVLink FTP ({@link FtpMissionUpload}, {@link FtpMissionDownload}), failing when the vehicle has
 * no FTP; AUTO FTP when the vehicle's AUTOPILOT_VERSION offers it, else items, and items again for
 * that transfer when FTP fails. A vehicle that never answered FTP is remembered: its later AUTO
 * transfers go item by item at once, until an FTP transfer (forced with the FTP path) succeeds. A
 * transfer that fell back to items says so first in its result's note.
 */
public final class MissionTransfers {

    /** The vehicle's messages of the mission protocol, the ones {@link #handle} takes. */
    public static final List<Class<? extends MAVLinkMessage>> MESSAGES = List.of(msg_mission_request.class,
            msg_mission_request_int.class, msg_mission_ack.class, msg_mission_count.class, msg_mission_item_int.class,
            msg_mission_item.class, msg_file_transfer_protocol.class);

    /** A transfer waiting its turn: an item transfer, the items of an upload (null for a download), or items only. */
    private record Queued(Transfer transfer, List<MissionItem> upload, boolean itemsOnly) {
    }

    private final VehicleChannel vehicle;
    private final ProtocolTimers timers;
    private final Supplier<MissionTransferConfig> config;
    private final MissionUploadProtocol upload;
    private final MissionDownloadProtocol download;
    private final FtpClient ftp;
    private final Deque<Queued> waiting = new ArrayDeque<>();
    private Transfer active;
    private boolean ftpUnanswered;

    /** @param config the timeouts and path of transfers started from now on (a command line may change them) */
    public MissionTransfers(VehicleChannel vehicle, ProtocolTimers timers, Supplier<MissionTransferConfig> config) {
        this.vehicle = vehicle;
        this.timers = timers;
        this.config = config;
        this.upload = new MissionUploadProtocol(this);
        this.download = new MissionDownloadProtocol(this);
        this.ftp = new FtpClient(new FtpChannel() {
            @Override
            public void send(MAVLinkMessage message) {
                vehicle.send(message);
            }

            @Override
            public int system() {
                return vehicle.system();
            }

            @Override
            public int component() {
                return vehicle.component();
            }

            @Override
            public int groundSystem() {
                return vehicle.groundSystem();
            }

            @Override
            public RoundTrip roundTrip() {
                return vehicle.roundTrip();
            }
        }, timers);
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

    /** The vehicle's MAVLink FTP client. */
    public FtpClient ftp() {
        return ftp;
    }

    /** Queues a download, or an upload that may go item by item only; from any thread. */
    void submit(Transfer transfer) {
        submit(transfer, null);
    }

    /** Queues an item transfer; an upload's {@code items} let it go over FTP instead. From any thread. */
    void submit(Transfer transfer, List<MissionItem> items) {
        boolean upload = transfer.what().startsWith("upload");
        timers.execute(() -> {
            waiting.add(new Queued(transfer, items, upload && items == null));
            pump();
        });
    }

    private void pump() {
        if (active == null && !waiting.isEmpty()) {
            Queued q = waiting.poll();
            Transfer t = q.itemsOnly() || !overFtp(q.transfer().config.path()) ? q.transfer() : overFtp(q);
            active = t;
            t.begin(() -> {
                if (active == t) {
                    active = null;
                    timers.execute(this::pump);
                }
            });
        }
    }

    private boolean overFtp(TransferPath path) {
        return switch (path) {
            case ITEMS -> false;
            case FTP -> true;
            case AUTO -> !ftpUnanswered && vehicle.offersFtp().orElse(false);
        };
    }

    /** The FTP transfer standing for an item transfer; its result goes to the item transfer's caller. */
    private FtpMissionTransfer overFtp(Queued q) {
        Transfer items = q.transfer();
        FtpMissionTransfer f = q.upload() != null
                ? new FtpMissionUpload(vehicle, timers, items.config, items.progress, items.type, q.upload(), ftp)
                : new FtpMissionDownload(vehicle, timers, items.config, items.progress, items.type, ftp);
        f.result.thenAccept(r -> {
            if (r.success()) {
                ftpUnanswered = false;
                items.result.complete(q.upload() != null ? TransferResult.verified(r.items(), r.resends(), 0, "over FTP")
                        : new TransferResult(true, null, r.items(), r.resends(), 0, false, "over FTP"));
            } else if (items.config.path() == TransferPath.AUTO) {
                // item by item, right after: its errors name the item the vehicle refuses
                ftpUnanswered |= f.unanswered();
                items.fallingBackFrom("item by item, as FTP failed (" + f.why() + ")");
                waiting.addFirst(new Queued(items, null, true));
            } else {
                items.result.complete(r);
            }
        });
        return f;
    }

    /**
     * A mission protocol message from the vehicle (MISSION_REQUEST, _INT, MISSION_ACK, MISSION_COUNT,
     * MISSION_ITEM_INT, MISSION_ITEM) or FILE_TRANSFER_PROTOCOL, on the protocol's thread; the others
     * are ignored.
     */
    public void handle(MAVLinkMessage message) {
        if (message instanceof msg_file_transfer_protocol m) {
            ftp.handle(m);
        } else if (message instanceof msg_mission_request m) {
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
