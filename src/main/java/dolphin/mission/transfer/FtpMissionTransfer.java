package dolphin.mission.transfer;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.mavlink.ProtocolTimers;
import dolphin.mavlink.ftp.FtpClient;
import dolphin.mavlink.ftp.FtpException;
import dolphin.mission.model.MissionType;
import java.util.Optional;
import java.util.concurrent.CompletionException;

/**
 * A mission, fence or rally transfer as one file over MAVLink FTP (docs/mavlink.md, "Mission
 * transfers over FTP"), queued with the item transfers of its vehicle. It stands for an item
 * transfer: {@link MissionTransfers} hands its result to that transfer's caller, or runs the item
 * transfer instead when it fails and the path is AUTO.
 */
abstract class FtpMissionTransfer extends Transfer {

    private static final String OVER_FTP = "over FTP: ";

    final FtpClient ftp;
    final String path;
    private boolean unanswered;
    private String itemsNote;       // why the items go instead, when FTP was given up on what the vehicle said

    FtpMissionTransfer(VehicleChannel vehicle, ProtocolTimers timers, MissionTransferConfig config, TransferProgress progress,
                       MissionType type, FtpClient ftp) {
        super(vehicle, timers, config, progress, type);
        this.ftp = ftp;
        this.path = MissionFtpFile.path(type);
    }

    /** Starts the file transfer. */
    abstract void run();

    @Override
    final void start() {
        if (vehicle.offersFtp().equals(Optional.of(false))) {
            unanswered = true;
            fail("the vehicle does not offer MAVLink FTP (no MAV_PROTOCOL_CAPABILITY_FTP in its AUTOPILOT_VERSION):"
                    + " transfer it item by item");
            return;
        }
        run();
    }

    @Override
    final void handle(MAVLinkMessage message) {
        // the mission protocol's messages belong to item transfers
    }

    /** Whether the vehicle never answered over FTP (or says it has no FTP): later AUTO transfers go item by item. */
    final boolean unanswered() {
        return unanswered && itemsNote == null;
    }

    /**
     * Gives FTP up before the vehicle answered it (it says it has none, or says nothing): the
     * transfer fails and AUTO goes item by item, saying {@code note} first. Not remembered: the
     * vehicle may answer the next transfer.
     */
    final void abandon(String note) {
        itemsNote = note;
        ftp.abandon(note);
        if (!done()) {
            failOverFtp(note);
        }
    }

    /** Why the items go instead of this transfer: the note it was given up with, or its failure. */
    final String itemsNote() {
        return itemsNote != null ? itemsNote : "item by item, as FTP failed (" + why() + ")";
    }

    /** Fails with the FTP client's reason. */
    final void failed(Throwable e) {
        Throwable cause = e instanceof CompletionException && e.getCause() != null ? e.getCause() : e;
        if (cause instanceof FtpException f) {
            unanswered = !f.answered();
            String verdict = f.refusedAtClose() && what().startsWith("upload")
                    ? ": ArduPilot could not read a complete list from it" : "";
            failOverFtp(f.getMessage() + verdict);
        } else {
            failOverFtp(String.valueOf(cause));
        }
    }

    /** Fails saying the FTP path did: "over FTP: why". */
    final void failOverFtp(String why) {
        fail(OVER_FTP + why);
    }

    /** Why the transfer failed, without the "over FTP: " of its reason. */
    final String why() {
        return reason().startsWith(OVER_FTP) ? reason().substring(OVER_FTP.length()) : reason();
    }

    /** Reports progress in bytes. */
    final void reportBytes(boolean upload, long done, long total, int resent) {
        progress.progress(new TransferStatus(type, upload, TransferPath.FTP, done, total, resent));
    }
}
