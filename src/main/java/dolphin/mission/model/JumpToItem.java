package dolphin.mission.model;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_set_current;
import java.util.List;

/**
 * {@code jumpToItem item, repetitions}: a ground-side jump, as in the original. When the vehicle reaches the item
 * before this command, the ground station sends MISSION_SET_CURRENT(item), at most
 * {@code repetitions} times per flight. {@code item} is the uploaded seq (home is 0).
 */
public final class JumpToItem extends DroneCommand {

    private final int item;
    private final int repetitions;

    public JumpToItem(int item, int repetitions) {
        this.item = item;
        this.repetitions = repetitions;
    }

    public int item() {
        return item;
    }

    public int repetitions() {
        return repetitions;
    }

    /** This jump with its item as a vehicle numbers it, when that is not as the runtime does (no home item: one less). */
    public JumpToItem numbered(int vehicleSeq) {
        return vehicleSeq == item ? this : new JumpToItem(vehicleSeq, repetitions);
    }

    @Override
    public String name() {
        return "jumpToItem";
    }

    @Override
    public List<MAVLinkMessage> messages(int system, int component) {
        msg_mission_set_current m = new msg_mission_set_current();
        m.target_system = (short) system;
        m.target_component = (short) component;
        m.seq = item;
        return List.of(m);
    }
}
