package dolphin.mavlink.mission;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.Position;
import dolphin.mavlink.MAVLinkNode;
import java.util.ArrayList;
import java.util.List;

/**
 * A command that becomes one or more mission items (report Listing 7). Its position may be null for
 * commands that have none (speed, delay, camera).
 */
public abstract class MissionPoint extends DroneCommand {

    private final Position position;

    protected MissionPoint(Position position) {
        this.position = position;
    }

    public Position getPosition() {
        return position;
    }

    /** The items, numbered from {@code seq}. */
    public abstract List<MissionItem> items(int seq);

    /** How many items {@link #items} emits; always equal to its size (F-4). */
    public int messageCount() {
        return items(0).size();
    }

    @Override
    public List<MAVLinkMessage> toMavLinkMessage(MAVLinkNode dest) {
        return toMavLinkMessage(dest, 0);
    }

    public List<MAVLinkMessage> toMavLinkMessage(MAVLinkNode dest, int seq) {
        List<MAVLinkMessage> out = new ArrayList<>();
        for (MissionItem i : items(seq)) {
            out.add(i.toMessage(dest.getMavLinkId(), dest.getAutopilotCompid()));
        }
        return out;
    }
}
