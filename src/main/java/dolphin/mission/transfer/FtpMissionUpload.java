package dolphin.mission.transfer;

import dolphin.mavlink.ProtocolTimers;
import dolphin.mavlink.ftp.FtpClient;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import java.util.List;
import java.util.Optional;

/**
 * Uploads a list as one file ({@link MissionFtpFile}), then reads the file back and compares it
 * with what was sent ({@link MissionVerification}): ArduPilot ACKs a TerminateSession repeated after
 * its refusal was lost, so only the read-back proves the vehicle holds the list. Progress counts the
 * bytes written and read back, twice the file's length in all.
 */
final class FtpMissionUpload extends FtpMissionTransfer {

    private final List<MissionItem> items;

    FtpMissionUpload(VehicleChannel vehicle, ProtocolTimers timers, MissionTransferConfig config, TransferProgress progress,
                     MissionType type, List<MissionItem> items, FtpClient ftp) {
        super(vehicle, timers, config, progress, type, ftp);
        this.items = List.copyOf(items);
    }

    @Override
    String what() {
        return "upload to";
    }

    @Override
    void run() {
        for (int i = 0; i < items.size(); i++) {
            if (items.get(i).seq() != i) {
                fail("item " + i + " has seq " + items.get(i).seq() + ": items must be numbered 0, 1, 2, ... in order");
                return;
            }
        }
        byte[] file = MissionFtpFile.encode(type, items);
        long total = 2L * file.length;
        ftp.write(path, file, config.timeouts(), (done, length, resent) -> reportBytes(true, done, total, resent))
                .thenCompose(written -> {
                    resends = written.resends();
                    return ftp.read(path, MissionFtpFile::length, config.timeouts(),
                            (done, length, resent) -> reportBytes(true, file.length + done, total, written.resends() + resent));
                })
                .whenComplete((read, e) -> {
                    if (e != null) {
                        failed(e);
                    } else {
                        resends += read.resends();
                        check(read.bytes());
                    }
                });
    }

    private void check(byte[] readBack) {
        List<MissionItem> held;
        try {
            held = MissionFtpFile.decode(readBack).items();
        } catch (IllegalArgumentException e) {
            failOverFtp(path + " read back is not a list: " + e.getMessage());
            return;
        }
        Optional<String> difference = MissionVerification.firstDifference(type, items, held);
        if (difference.isPresent()) {
            failOverFtp(path + " read back differs from what was sent: " + difference.get());
        } else {
            succeed(items);
        }
    }
}
