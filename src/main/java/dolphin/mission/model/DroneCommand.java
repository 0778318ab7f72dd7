package dolphin.mission.model;

import com.MAVLink.Messages.MAVLinkMessage;
import java.util.List;

/**
 * One command of a mission as the script wrote it. Mission points become
 * mission items; the other commands are sent by the ground station at a point of the flight
 * (keyed by item seq: docs/decisions.md, "Missions"), like the ground-side {@code jumpToItem}.
 */
public abstract class DroneCommand {

    /** The DSL word that made this command, for messages and tables. */
    public abstract String name();

    /** True for commands sent before the upload (key 0) rather than when an item is reached. */
    public boolean executeOnStartup() {
        return false;
    }

    /**
     * What the ground station sends a vehicle for this command when its place in the flight comes;
     * nothing for mission points, which are flown as items.
     */
    public List<MAVLinkMessage> messages(int system, int component) {
        return List.of();
    }
}
