package dolphin.mission.model;

import com.MAVLink.enums.MAV_FRAME;
import java.util.List;

/** One mission item as it is, e.g. downloaded from a vehicle: a point that emits exactly that item. */
public final class RawItemPoint extends MissionPoint {

    private final MissionItem item;

    public RawItemPoint(MissionItem item) {
        super("item", positional(item) ? item.position() : null);
        this.item = item;
    }

    public MissionItem item() {
        return item;
    }

    @Override
    public List<MissionItem> items(int seq) {
        return List.of(item.withSeq(seq));
    }

    /** A mission of raw items: item 0 is its home (when positional), items 1.. its points. */
    public static Mission mission(String name, List<MissionItem> items) {
        dolphin.core.Position home = !items.isEmpty() && positional(items.get(0)) ? items.get(0).position() : null;
        return mission(name, home, items, false);
    }

    /**
     * A mission of items 1, 2, ... with the given home (null: the vehicle's own, and no DO_SET_HOME),
     * items lower than home plus the clearance allowed or not (HeightCheck).
     */
    public static Mission mission(String name, dolphin.core.Position home, List<MissionItem> items, boolean belowHomeAllowed) {
        List<DroneCommand> points = items.stream().skip(1).<DroneCommand>map(RawItemPoint::new).toList();
        return new Mission(name, home, points, belowHomeAllowed);
    }

    private static boolean positional(MissionItem i) {
        return i.frame() != MAV_FRAME.MAV_FRAME_MISSION && (i.x() != 0 || i.y() != 0);
    }

    @Override
    public String toString() {
        return item.commandName() + " " + item;
    }
}
