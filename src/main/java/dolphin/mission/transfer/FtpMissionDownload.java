package dolphin.mission.transfer;

import dolphin.mavlink.ProtocolTimers;
import dolphin.mavlink.ftp.FtpClient;
import dolphin.mission.model.MissionType;

/** Downloads a list as one file ({@link MissionFtpFile}): a burst read to the length its header gives. */
final class FtpMissionDownload extends FtpMissionTransfer {

    FtpMissionDownload(VehicleChannel vehicle, ProtocolTimers timers, MissionTransferConfig config, TransferProgress progress,
                       MissionType type, FtpClient ftp) {
        super(vehicle, timers, config, progress, type, ftp);
    }

    @Override
    String what() {
        return "download from";
    }

    @Override
    void run() {
        ftp.read(path, MissionFtpFile::length, config.timeouts(), (done, total, resent) -> reportBytes(false, done, total, resent))
                .whenComplete((read, e) -> {
                    if (e != null) {
                        failed(e);
                        return;
                    }
                    resends = read.resends();
                    MissionFtpFile.Contents c;
                    try {
                        c = MissionFtpFile.decode(read.bytes());
                    } catch (IllegalArgumentException x) {
                        failOverFtp(path + " is not a list: " + x.getMessage());
                        return;
                    }
                    if (c.type() != type) {
                        failOverFtp(path + " holds the " + c.type().label() + " instead");
                    } else {
                        succeed(c.items());
                    }
                });
    }
}
