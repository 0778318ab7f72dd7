package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.core.Position;
import com.MAVLink.enums.MAV_MISSION_RESULT;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.transfer.StoredItems;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;

/**
 * The mission a simulated vehicle stores, as ArduPilot's AP_Mission keeps it: index 0 is always
 * home (written items at seq 0 are dropped, and reading seq 0 gives the vehicle's current home as a
 * NAV_WAYPOINT in MAV_FRAME_GLOBAL, height above mean sea level); real items start at 1.
 */
final class MissionStore implements ItemStore {

    private final List<MissionItem> items = new ArrayList<>();
    private final Supplier<Position> home;
    private final int capacity;
    /** Whether the vehicle is ArduPlane, which keeps other parameters of a NAV_WAYPOINT. */
    private final boolean plane;

    MissionStore(Supplier<Position> home, int capacity, boolean plane) {
        this.home = home;
        this.capacity = capacity;
        this.plane = plane;
        items.add(null);
    }

    @Override
    public int capacity() {
        return capacity;
    }

    /** Items stored, home included (what MISSION_COUNT reports on download). */
    @Override
    public int count() {
        return items.size();
    }

    @Override
    public MissionType type() {
        return MissionType.MISSION;
    }

    @Override
    public int check(MissionItem item) {
        return MissionCheck.result(item, plane);
    }

    @Override
    public boolean jumpsNowhere(MissionItem item, int count) {
        return MissionCheck.jumpsNowhere(item, count);
    }

    @Override
    public Optional<String> receivedText() {
        return Optional.of("Flight plan received");
    }

    /** Each item was checked as it came: the mission is stored as it arrived. */
    @Override
    public int complete() {
        return MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
    }

    MissionItem get(int seq) {
        return seq == 0 ? homeItem() : items.get(seq);
    }

    /** Keeps the first {@code n} items (home always stays), as MISSION_COUNT does at once. */
    @Override
    public void truncate(int n) {
        while (items.size() > Math.max(1, n)) {
            items.remove(items.size() - 1);
        }
    }

    /** Writes an item at its seq (seq 0 is home and is not written; seq may be at most count()). */
    @Override
    public void put(MissionItem item) {
        int seq = item.seq();
        if (seq == 0) {
            return;
        }
        if (seq < items.size()) {
            items.set(seq, item);
        } else if (seq == items.size()) {
            items.add(item);
        } else {
            throw new IllegalArgumentException("mission item " + seq + " written after only " + items.size());
        }
    }

    /** An item as a download reports it: what ArduPilot keeps of it ({@link StoredItems}), home included. */
    @Override
    public MissionItem reported(int seq) {
        return seq == 0 ? StoredItems.home(home.get()) : StoredItems.missionItem(get(seq), plane);
    }

    @Override
    public void clear() {
        truncate(1);
    }

    /** Every item, home first. */
    List<MissionItem> items() {
        List<MissionItem> all = new ArrayList<>(items.size());
        for (int i = 0; i < items.size(); i++) {
            all.add(get(i));
        }
        return all;
    }

    private MissionItem homeItem() {
        Position h = home.get();
        return new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL, 0, 0, 0, 0,
                MissionItem.degE7(h.latitudeDegrees()), MissionItem.degE7(h.longitudeDegrees()), (float) h.hae(), true);
    }
}
