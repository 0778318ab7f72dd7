package dolphin.mission.transfer;

import dolphin.mission.model.MissionItem;
import dolphin.core.EnvironmentException;
import java.util.List;

/**
 * How a mission upload or download ended: success with the items (those uploaded, or those
 * downloaded, item 0 included), or failure with a message a user can act on, e.g.
 * "upload to vehicle 2 failed: item 3 (NAV_WAYPOINT): MAV_MISSION_INVALID_PARAM7 (z = NaN)".
 *
 * @param resends messages sent again (MISSION_COUNT, items, requests) because of a timeout or a repeated request
 * @param ignoredAcks MAV_MISSION_INVALID_SEQUENCE ACKs ignored during an upload (noisy links, as QGC does)
 * @param verified an upload whose list the transfer itself read back from the vehicle and found equal
 *                 ({@link MissionVerification}): nobody needs to download it again to check
 * @param note how the transfer went when a user may want to know ("over FTP", "the final ACK was
 *             lost; the download shows the whole mission on the vehicle"), or empty
 * @param planId the vehicle's id of the list it holds after the transfer (MISSION_ACK.opaque_id of an upload,
 *               MISSION_COUNT.opaque_id of a download: PX4 sends the list's CRC32), 0 when the vehicle gives none
 */
public record TransferResult(boolean success, String error, List<MissionItem> items, int resends, int ignoredAcks,
                             boolean verified, String note, long planId) {

    public TransferResult {
        items = items == null ? List.of() : List.copyOf(items);
        note = note == null ? "" : note;
    }

    public TransferResult(boolean success, String error, List<MissionItem> items, int resends, int ignoredAcks,
                          boolean verified, String note) {
        this(success, error, items, resends, ignoredAcks, verified, note, 0);
    }

    public TransferResult(boolean success, String error, List<MissionItem> items, int resends, int ignoredAcks) {
        this(success, error, items, resends, ignoredAcks, false, "");
    }

    static TransferResult ok(List<MissionItem> items, int resends, int ignoredAcks) {
        return new TransferResult(true, null, items, resends, ignoredAcks);
    }

    /** An upload read back and found equal, with how it went. */
    static TransferResult verified(List<MissionItem> items, int resends, int ignoredAcks, String note) {
        return new TransferResult(true, null, items, resends, ignoredAcks, true, note);
    }

    static TransferResult failed(String error, int resends, int ignoredAcks) {
        return new TransferResult(false, error, List.of(), resends, ignoredAcks);
    }

    /** The same result with {@code first} before its note. */
    TransferResult notedFirst(String first) {
        return new TransferResult(success, error, items, resends, ignoredAcks, verified,
                note.isEmpty() ? first : first + "; " + note, planId);
    }

    /** The same result with the vehicle's id of the list. */
    TransferResult withPlanId(long id) {
        return new TransferResult(success, error, items, resends, ignoredAcks, verified, note, id);
    }

    /** The same result with other items (the same list numbered another way). */
    TransferResult withItems(List<MissionItem> other) {
        return new TransferResult(success, error, other, resends, ignoredAcks, verified, note, planId);
    }

    /** The items, or an EnvironmentException with the error. */
    public List<MissionItem> orThrow() {
        if (!success) {
            throw new EnvironmentException(error);
        }
        return items;
    }

    @Override
    public String toString() {
        return success ? "success (" + items.size() + " items, " + resends + " resends)" : error;
    }
}
