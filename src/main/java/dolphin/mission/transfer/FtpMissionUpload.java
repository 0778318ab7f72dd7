package dolphin.mission.transfer;

import dolphin.core.Position;
import dolphin.mavlink.ProtocolTimers;
import dolphin.mavlink.VehicleFamily;
import dolphin.mavlink.ftp.FileCrc32;
import dolphin.mavlink.ftp.FtpClient;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;

/**
 * Uploads a list as one file ({@link MissionFtpFile}), then has it read back: ArduPilot ACKs a
 * TerminateSession repeated after its refusal was lost, so only the read-back proves the vehicle
 * holds the list. The vehicle reads it itself and answers with its CRC32 (asked right behind the
 * TerminateSession, {@link FtpClient#writeChecked}), compared with that of the file predicted from
 * what was sent; when they differ, the file is read back over the link and
 * compared item by item ({@link MissionVerification}). Progress counts the bytes written and read
 * back, twice the file's length in all.
 */
final class FtpMissionUpload extends FtpMissionTransfer {

    /** How long the check waits for the vehicle's home, when it has not reported it: 1 s, in looks 50 ms apart. */
    private static final Duration HOME_LOOK = Duration.ofMillis(50);
    private static final int HOME_LOOKS = 20;

    private final List<MissionItem> items;
    private int homeLooks;

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
        if (type == MissionType.MISSION && vehicle.home() == null) {
            // a vehicle just heard may not have sent its home yet: asked now, it is there for the check
            vehicle.askHome();
        }
        byte[] file = MissionFtpFile.encode(type, items);
        long total = 2L * file.length;
        ftp.writeChecked(path, file, config.timeouts(), (done, length, resent) -> reportBytes(true, done, total, resent))
                .whenComplete((written, e) -> {
                    if (e != null) {
                        failed(e);
                    } else {
                        resends = written.file().resends();
                        verify(written.vehicleCrc(), file.length, total);
                    }
                });
    }

    /**
     * Compares the vehicle's CRC32 of the file it holds with that of the file predicted from what
     * was sent ({@link StoredItems}): equal, the list is verified at no cost; otherwise (a
     * prediction that misses, a vehicle without CalcFileCRC32) the whole file is read back and
     * compared item by item. A mission's item 0 is the vehicle's home, which it fills in itself: the
     * CRC is first compared with the prediction of a vehicle whose home is not set (item 0 all
     * zeros, as ArduPilot reads it then), then with one of the home it reported, waiting up to 1 s
     * for that home (asked for when the upload began) when it has not reported one yet.
     */
    private void verify(OptionalLong vehicleCrc, long written, long total) {
        if (vehicleCrc.isEmpty()) {
            readBack(written, total);
        } else if (vehicleCrc.getAsLong() == FileCrc32.of(StoredItems.file(type, items, null, plane()))) {
            verified(total);
        } else {
            compareWithHome(vehicleCrc.getAsLong(), written, total);
        }
    }

    /** The CRC compared with the prediction of the home the vehicle reported, looked for up to 1 s. */
    private void compareWithHome(long vehicleCrc, long written, long total) {
        Position home = vehicle.home();
        if (type == MissionType.MISSION && home == null && homeLooks++ < HOME_LOOKS) {
            timers.schedule(HOME_LOOK, () -> compareWithHome(vehicleCrc, written, total));
        } else if (home != null && vehicleCrc == FileCrc32.of(StoredItems.file(type, items, home, plane()))) {
            verified(total);
        } else {
            readBack(written, total);
        }
    }

    private boolean plane() {
        return vehicle.family().firmware() == VehicleFamily.PLANE;
    }

    private void verified(long total) {
        reportBytes(true, total, total, resends);
        succeed(items);
    }

    private void readBack(long written, long total) {
        ftp.read(path, MissionFtpFile::length, config.timeouts(),
                        (done, length, resent) -> reportBytes(true, written + done, total, resends + resent))
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
