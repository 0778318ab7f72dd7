package dolphin.sim;

import dolphin.mission.model.MissionItem;
import java.util.List;

/**
 * What a firmware's arming checks see of the vehicle's mission.
 *
 * @param items the stored mission, home first
 * @param current the current nav item (0: none)
 * @param running whether the mission runs (MISSION_CURRENT ACTIVE)
 */
record MissionView(List<MissionItem> items, int current, boolean running) {
}
