package dolphin.sim;

import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;

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

    /** The MAV_MISSION_RESULT once the last item arrived: the list as a whole. */
    int complete();

    /** An item as a download reports it. */
    MissionItem reported(int seq);

    void clear();
}
