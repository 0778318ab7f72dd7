package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_MISSION_RESULT;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import java.nio.ByteBuffer;
import java.util.List;
import java.util.zip.CRC32;

/**
 * A PX4 vehicle's mission as its mission protocol transfers it: no home item, the first item is seq 0
 * (MavlinkMissionManager), DO_JUMP targets numbered alike. The vehicle stores it as every simulated
 * vehicle does, home first ({@link MissionStore}); this list shifts each seq by one on the way in and
 * out, checks items as PX4 does ({@link Px4MissionCheck}) and gives back what PX4 keeps of them.
 */
final class Px4MissionList implements ItemStore {

    private final MissionStore store;

    Px4MissionList(MissionStore store) {
        this.store = store;
    }

    @Override
    public MissionType type() {
        return MissionType.MISSION;
    }

    @Override
    public int capacity() {
        return store.capacity() - 1;
    }

    @Override
    public int count() {
        return store.count() - 1;
    }

    @Override
    public void truncate(int n) {
        store.truncate(n + 1);
    }

    @Override
    public void put(MissionItem item) {
        store.put(renumbered(item, 1));
    }

    @Override
    public int check(MissionItem item) {
        return Px4MissionCheck.result(item);
    }

    /** PX4 checks the mission's jumps in its feasibility check, not at upload. */
    @Override
    public boolean jumpsNowhere(MissionItem item, int count) {
        return false;
    }

    @Override
    public int complete() {
        return MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
    }

    /**
     * PX4's CRC32 of the mission (MavlinkMissionManager::crc32_for_mission_item), here over what it keeps of each
     * item; 0 without items, as PX4's.
     */
    @Override
    public long planId() {
        List<MissionItem> stored = store.items();
        if (stored.size() <= 1) {
            return 0;
        }
        CRC32 crc = new CRC32();
        ByteBuffer b = ByteBuffer.allocate(48);
        for (MissionItem i : stored.subList(1, stored.size())) {
            b.clear();
            b.putInt(i.command()).putInt(i.frame()).putFloat(i.param1()).putFloat(i.param2()).putFloat(i.param3())
                    .putFloat(i.param4()).putInt(i.x()).putInt(i.y()).putFloat(i.z()).put((byte) (i.autocontinue() ? 1 : 0));
            crc.update(b.array(), 0, b.position());
        }
        return crc.getValue();
    }

    @Override
    public MissionItem reported(int seq) {
        return Px4MissionCheck.stored(renumbered(store.get(seq + 1), -1));
    }

    @Override
    public void clear() {
        store.clear();
    }

    private static MissionItem renumbered(MissionItem i, int by) {
        float p1 = i.command() == MAV_CMD.MAV_CMD_DO_JUMP ? i.param1() + by : i.param1();
        return new MissionItem(i.seq() + by, i.command(), i.frame(), p1, i.param2(), i.param3(), i.param4(), i.x(), i.y(), i.z(),
                i.autocontinue());
    }
}
