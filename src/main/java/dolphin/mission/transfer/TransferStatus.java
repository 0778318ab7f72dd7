package dolphin.mission.transfer;

import dolphin.mission.model.MissionType;
import java.util.Locale;

/**
 * Where a transfer stands, as {@link TransferProgress} reports it: {@code done} of {@code total}
 * items (mission protocol) or bytes (FTP), and the messages sent again so far.
 *
 * @param path {@link TransferPath#ITEMS} or {@link TransferPath#FTP}, never AUTO
 * @param total -1 while unknown (a download before the vehicle said how much it holds)
 */
public record TransferStatus(MissionType type, boolean upload, TransferPath path, long done, long total, int resends) {

    /** "items" or "bytes". */
    public String unit() {
        return path == TransferPath.FTP ? "bytes" : "items";
    }

    /** "uploading the fence over FTP: 620 of 1,530 bytes, 2 resent". */
    public String text() {
        String list = type == MissionType.MISSION ? "" : " the " + type.label();
        String how = path == TransferPath.FTP ? " over FTP" : "";
        String amount = total < 0 ? "" : String.format(Locale.ROOT, ": %,d of %,d %s", done, total, unit());
        return (upload ? "uploading" : "downloading") + list + how + amount + (resends == 0 ? "" : ", " + resends + " resent");
    }
}
