package dolphin.sim;

import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import java.util.Optional;

/**
 * One list a simulated vehicle stores and the mission protocol transfers: its mission, fence or
 * rally points ({@link MissionItemProtocol} runs the protocol, the same for all three).
 */
interface ItemStore {

    MissionType type();

    int capacity();

    /** Items stored (what MISSION_COUNT reports on download). */
    int count();

    /** An upload of {@code n} items begins. */
    void truncate(int n);

    /** Stores an uploaded item at its seq. */
    void put(MissionItem item);

    /** The MAV_MISSION_RESULT for an item as it arrives. */
    int check(MissionItem item);

    /** Whether an uploaded DO_JUMP leads outside a list of {@code count} items, which the upload refuses (MAV_MISSION_ERROR). */
    default boolean jumpsNowhere(MissionItem item, int count) {
        return false;
    }

    /** Said (INFO) once an upload completed; empty: nothing. */
    default Optional<String> receivedText() {
        return Optional.empty();
    }

    /**
     * The list's id, which MISSION_ACK and MISSION_COUNT carry (opaque_id) and MISSION_CURRENT names; 0 when the
     * autopilot gives none (ArduPilot).
     */
    default long planId() {
        return 0;
    }

    /** The MAV_MISSION_RESULT once the last item arrived: the list as a whole. */
    int complete();

    /** An item as a download reports it. */
    MissionItem reported(int seq);

    void clear();
}
