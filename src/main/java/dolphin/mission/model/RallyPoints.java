package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.ArrayList;
import java.util.List;

/**
 * Rally points: where a vehicle may go instead of home when it returns (RTL), as the
 * MAV_MISSION_TYPE_RALLY items that carry them, one MAV_CMD_NAV_RALLY_POINT each (docs/airspace.md).
 * Like {@link Fence}, the items are the truth, so that a file's rally points write back as they came.
 *
 * <p>ArduPilot (MissionItemProtocol_Rally) accepts the frames GLOBAL (heights above mean sea level,
 * what the scripts use), GLOBAL_RELATIVE_ALT (above home, what QGroundControl sends) and
 * GLOBAL_TERRAIN_ALT, and stores the height as a whole number of metres between -32768 and 32767.
 */
public record RallyPoints(List<MissionItem> items) {

    public static final RallyPoints NONE = new RallyPoints(List.of());

    /** Use {@link #of}, which checks the items: this takes them as they are. */
    public RallyPoints {
        items = List.copyOf(items);
    }

    /**
     * The rally points of a list of items, numbered again from 0.
     *
     * @throws BadItemException naming an item that is not a NAV_RALLY_POINT at a position ArduPilot takes
     */
    public static RallyPoints of(List<MissionItem> rallyItems) {
        List<MissionItem> items = new ArrayList<>();
        for (int i = 0; i < rallyItems.size(); i++) {
            MissionItem it = rallyItems.get(i).withSeq(i);
            if (it.command() != MAV_CMD.MAV_CMD_NAV_RALLY_POINT) {
                throw new BadItemException(i, "rally item " + i + ": " + it.commandName() + " is not NAV_RALLY_POINT");
            }
            if (!ItemText.isGlobal(it.frame())) {
                throw new BadItemException(i, "rally item " + i + ": frame " + it.frameName() + " is not one ArduPilot"
                        + " takes for a rally point (GLOBAL, GLOBAL_RELATIVE_ALT or GLOBAL_TERRAIN_ALT)");
            }
            if (!(Math.abs(it.z()) <= Short.MAX_VALUE)) {
                throw new BadItemException(i, "rally item " + i + ": height " + ItemText.number(it.z()) + " m is out"
                        + " of ArduPilot's range for rally points (-32768 to 32767 m)");
            }
            Fence.requireInRange(i, it);
            items.add(it);
        }
        return new RallyPoints(items);
    }

    /**
     * Rally points at positions whose heights are above mean sea level (MAV_FRAME_GLOBAL_INT),
     * rounded to whole metres as ArduPilot stores them, so that the download matches the upload.
     */
    public static RallyPoints at(List<Position> points) {
        List<MissionItem> items = new ArrayList<>();
        for (Position p : points) {
            items.add(new MissionItem(items.size(), MAV_CMD.MAV_CMD_NAV_RALLY_POINT, MissionItem.GLOBAL_INT, 0, 0, 0, 0,
                    MissionItem.degE7(p.latitudeDegrees()), MissionItem.degE7(p.longitudeDegrees()),
                    (float) Math.rint(p.hae()), false));
        }
        return of(items);
    }

    /** The points, each with its item's height (above what its frame says). */
    public List<Position> points() {
        return items.stream().map(MissionItem::position).toList();
    }

    public boolean isEmpty() {
        return items.isEmpty();
    }

    public int size() {
        return items.size();
    }
}
