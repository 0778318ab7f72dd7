package dolphin.mission.model;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.mavlink.MAVLinkNode;
import java.util.List;

/**
 * One command of a mission as the script wrote it (report Listing 6). Mission points become
 * mission items; the other commands are sent by the ground station at a point of the flight
 * (keyed by item seq, design §5), like the ground-side {@code jumpToItem}.
 */
public abstract class DroneCommand {

    /** The DSL word that made this command, for messages and tables. */
    public abstract String name();

    /** True for commands sent before the upload (key 0) rather than when an item is reached. */
    public boolean executeOnStartup() {
        return false;
    }

    /** The messages that carry this command to a vehicle (for non-mission commands). */
    public abstract List<MAVLinkMessage> toMavLinkMessage(MAVLinkNode dest);
}
