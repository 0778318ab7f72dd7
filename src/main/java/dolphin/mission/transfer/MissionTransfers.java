package dolphin.mission.transfer;

import dolphin.mavlink.LinkRequests;
import dolphin.mavlink.ProtocolTimers;
import dolphin.mavlink.RoundTrip;
import dolphin.mavlink.ftp.FtpChannel;
import dolphin.mavlink.ftp.FtpClient;
import dolphin.mavlink.ftp.FtpPacing;
import dolphin.mission.model.MissionItem;
import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_file_transfer_protocol;
import com.MAVLink.common.msg_mission_ack;
import com.MAVLink.common.msg_mission_count;
import com.MAVLink.common.msg_mission_item;
import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.common.msg_mission_request;
import com.MAVLink.common.msg_mission_request_int;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
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
 * transfers go item by item at once, until an FTP transfer (forced with the FTP path) succeeds. An
 * AUTO transfer whose vehicle has not yet said what it offers asks it again and tries FTP
 * meanwhile: an FTP answer proves FTP, as the vehicle's "no FTP" or {@link #CAPABILITY_WAIT}
 * without either answer sends it item by item (docs/radios.md, "What the vehicle offers"). An AUTO
 * transfer that goes item by item says why first in its result's note.
 */
public final class MissionTransfers {

    /** The vehicle's messages of the mission protocol, the ones {@link #handle} takes. */
    public static final List<Class<? extends MAVLinkMessage>> MESSAGES = List.of(msg_mission_request.class,
            msg_mission_request_int.class, msg_mission_ack.class, msg_mission_count.class, msg_mission_item_int.class,
            msg_mission_item.class, msg_file_transfer_protocol.class);

    /**
     * How long an AUTO transfer tries FTP on a vehicle that has not said whether it offers it, before
     * it goes item by item when neither that answer nor an FTP one came: a round trip or two on a
     * radio, with an ask lost on the way.
     */
    static final Duration CAPABILITY_WAIT = Duration.ofSeconds(3);
    /** A vehicle asked more often than this in vain has nothing to say: AUTO no longer tries FTP on it. */
    static final int PATIENT_ASKS = 3;
    private static final Duration CAPABILITY_POLL = Duration.ofMillis(50);
    private static final String NO_FTP = "item by item: the vehicle offers no MAVLink FTP";

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

            @Override
            public int radioBufferFree() {
                return vehicle.radioBufferFree();
            }

            @Override
            public LinkRequests linkRequests() {
                return vehicle.linkRequests();
            }

            @Override
            public FtpPacing pacing() {
                return vehicle.throughRadio() ? FtpPacing.RADIO : FtpPacing.NETWORK;
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
        if (active != null || waiting.isEmpty()) {
            return;
        }
        Queued q = waiting.poll();
        PathChoice choice = q.itemsOnly() ? PathChoice.ITEMS_ONLY : choose(q.transfer().config.path());
        Transfer t = choice.ftp() ? overFtp(q) : q.transfer();
        if (!choice.ftp() && !choice.why().isEmpty()) {
            t.pathNote(choice.why());
        }
        active = t;
        t.begin(() -> {
            if (active == t) {
                active = null;
                timers.execute(this::pump);
            }
        });
        if (choice.untilTold() && t instanceof FtpMissionTransfer f) {
            watch(f, timers.nanoTime());
        }
    }

    /**
     * The path a transfer takes and why, when a user may want to know; {@code untilTold}: FTP tried
     * on a vehicle that has not said whether it offers it, until it answers either.
     */
    private record PathChoice(boolean ftp, String why, boolean untilTold) {
        static final PathChoice ITEMS_ONLY = items("");

        static PathChoice items(String why) {
            return new PathChoice(false, why, false);
        }
    }

    private PathChoice choose(TransferPath path) {
        if (path != TransferPath.AUTO) {
            return new PathChoice(path == TransferPath.FTP, "", false);
        }
        if (ftpUnanswered) {
            return PathChoice.items("item by item, as MAVLink FTP went unanswered before");
        }
        if (!vehicle.autopilot().missionFtp()) {
            return PathChoice.items("item by item: " + vehicle.autopilot() + " keeps no mission in MAVLink FTP");
        }
        Optional<Boolean> offers = vehicle.offersFtp();
        if (offers.isPresent()) {
            return offers.get() ? new PathChoice(true, "", false) : PathChoice.items(NO_FTP);
        }
        if (vehicle.unansweredAsks() > PATIENT_ASKS) {
            return PathChoice.items(notTold());
        }
        vehicle.askWhatItOffers();
        return new PathChoice(true, "", true);
    }

    /**
     * Looks every {@link #CAPABILITY_POLL} at an FTP transfer tried on a vehicle that has not said
     * whether it offers FTP: once the vehicle answers over FTP or says it offers it, the transfer
     * goes on; said it does not, or {@link #CAPABILITY_WAIT} passed without either answer, it is
     * given up and the list goes item by item.
     */
    private void watch(FtpMissionTransfer f, long since) {
        timers.schedule(CAPABILITY_POLL, () -> {
            Optional<Boolean> offers = vehicle.offersFtp();
            if (f.done() || ftp.heard() || offers.equals(Optional.of(true))) {
                return;
            }
            if (offers.isPresent()) {
                f.abandon(NO_FTP);
            } else if (timers.nanoTime() - since >= CAPABILITY_WAIT.toNanos()) {
                f.abandon(notTold());
            } else {
                watch(f, since);
            }
        });
    }

    private String notTold() {
        int asks = vehicle.unansweredAsks();
        return "item by item: the vehicle has not said whether it offers MAVLink FTP (AUTOPILOT_VERSION asked "
                + asks + (asks == 1 ? " time)" : " times)");
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
                items.pathNote(f.itemsNote());
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
