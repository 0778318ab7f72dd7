package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import com.MAVLink.enums.MAV_MISSION_RESULT;
import dolphin.mission.model.BadItemException;
import dolphin.mission.model.Fence;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.transfer.StoredItems;
import dolphin.mission.model.RallyPoints;
import java.util.ArrayList;
import java.util.List;

/**
 * A simulated vehicle's fence or rally points, kept as ArduPilot keeps them (docs/airspace.md):
 * a fence upload replaces the stored fence only once complete and valid as a whole
 * (AC_PolyFence_loader writes the new fence at the end; a broken one is MAV_MISSION_ERROR and the old
 * fence stays); rally points are written as they arrive, as MissionItemProtocol_Rally does (COUNT
 * truncates, each item replaces or appends, so a refused one leaves the points before it); a
 * download reports what ArduPilot stores: a fence item's command, param1 and position, in
 * MAV_FRAME_GLOBAL at altitude 0; a rally point's position with its height as a whole number of
 * metres (a 16-bit integer in RallyLocation) in its altitude reference.
 */
final class AirspaceStore implements ItemStore {

    private final MissionType type;
    private final int capacity;
    /** What is stored, checked as a whole when its upload completed; the other stays empty. */
    private Fence fence = Fence.NONE;
    private RallyPoints rally = RallyPoints.NONE;
    private final List<MissionItem> incoming = new ArrayList<>();

    AirspaceStore(MissionType type, int capacity) {
        this.type = type;
        this.capacity = capacity;
    }

    @Override
    public MissionType type() {
        return type;
    }

    @Override
    public int capacity() {
        return capacity;
    }

    @Override
    public int count() {
        return items().size();
    }

    @Override
    public void truncate(int n) {
        incoming.clear();
        if (type == MissionType.RALLY) {
            rally = new RallyPoints(rally.items().subList(0, Math.min(n, rally.size())));
        } else if (n == 0) {
            clear();
        }
    }

    /** A fence item waits for the whole fence; a rally point replaces the one at its seq, or is appended. */
    @Override
    public void put(MissionItem item) {
        if (type == MissionType.FENCE) {
            incoming.add(item);
            return;
        }
        List<MissionItem> points = new ArrayList<>(rally.items());
        if (item.seq() < points.size()) {
            points.set(item.seq(), item);
        } else {
            points.add(item.withSeq(points.size()));
        }
        rally = new RallyPoints(points);
    }

    @Override
    public int check(MissionItem item) {
        boolean ours = type == MissionType.FENCE ? Fence.isFenceCommand(item.command())
                : item.command() == MAV_CMD.MAV_CMD_NAV_RALLY_POINT;
        if (!ours) {
            return MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED;
        }
        if (item.frame() == MAV_FRAME.MAV_FRAME_MISSION) {
            return MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED_FRAME;
        }
        int position = MissionCheck.position(item);
        if (position != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
            return position;
        }
        if (type == MissionType.RALLY && !(Math.abs(item.z()) <= Short.MAX_VALUE)) {
            return MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM7;
        }
        return MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
    }

    /** A fence is checked whole here; rally points were checked and stored one by one. */
    @Override
    public int complete() {
        if (type == MissionType.RALLY) {
            return MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
        }
        try {
            fence = Fence.of(incoming);
            return MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
        } catch (BadItemException e) {
            return MAV_MISSION_RESULT.MAV_MISSION_ERROR;
        } finally {
            incoming.clear();
        }
    }

    @Override
    public MissionItem reported(int seq) {
        MissionItem i = items().get(seq).withSeq(seq);
        return type == MissionType.FENCE ? StoredItems.fenceItem(i) : StoredItems.rallyItem(i);
    }

    @Override
    public void clear() {
        fence = Fence.NONE;
        rally = RallyPoints.NONE;
        incoming.clear();
    }

    Fence fence() {
        return fence;
    }

    RallyPoints rally() {
        return rally;
    }

    /** The stored items, numbered from 0. */
    private List<MissionItem> items() {
        return type == MissionType.FENCE ? fence.items() : rally.items();
    }
}
