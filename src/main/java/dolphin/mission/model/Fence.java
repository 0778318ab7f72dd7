package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.Position;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * A geofence: its regions and an optional breach return point, and the MAV_MISSION_TYPE_FENCE
 * items that carry them over the mission protocol (docs/airspace.md).
 *
 * <p>The items are the truth: a fence read from a file keeps its items as the file has them (frame,
 * altitude, autocontinue), so that writing it back in the same format gives the same items. A fence
 * built from regions gets the items QGroundControl's GeoFenceManager sends: polygons first, one
 * item a vertex (POLYGON_VERTEX_INCLUSION/EXCLUSION, param1 the vertex count), then circles
 * (CIRCLE_INCLUSION/EXCLUSION, param1 the radius), then the return point (FENCE_RETURN_POINT).
 */
public final class Fence {

    public static final Fence NONE = new Fence(List.of(), List.of(), null);

    private final List<MissionItem> items;
    private final List<FenceRegion> regions;
    private final Position returnPoint;

    private Fence(List<MissionItem> items, List<FenceRegion> regions, Position returnPoint) {
        this.items = List.copyOf(items);
        this.regions = List.copyOf(regions);
        this.returnPoint = returnPoint;
    }

    /** True for the five fence commands (5000 to 5004). */
    public static boolean isFenceCommand(int command) {
        return command == MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT
                || command == MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION
                || command == MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION
                || command == MAV_CMD.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION
                || command == MAV_CMD.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION;
    }

    /**
     * The fence of a list of fence items, numbered again from 0; the checks ArduPilot and
     * QGroundControl make when they load one: only fence commands, a polygon's vertices one after
     * the other with the same command and vertex count (at least 3), circles of a positive radius,
     * at most one return point, latitudes and longitudes in range.
     *
     * @throws BadItemException naming the item that breaks a rule
     */
    public static Fence of(List<MissionItem> fenceItems) {
        List<MissionItem> items = new ArrayList<>();
        List<FenceRegion> regions = new ArrayList<>();
        Position returnPoint = null;
        List<Position> polygon = new ArrayList<>();
        int polygonCommand = 0;
        int polygonSize = 0;
        int polygonStart = 0;
        for (int i = 0; i < fenceItems.size(); i++) {
            MissionItem it = fenceItems.get(i).withSeq(i);
            items.add(it);
            int command = it.command();
            if (!isFenceCommand(command)) {
                throw new BadItemException(i, "fence item " + i + ": " + it.commandName() + " is not a fence command"
                        + " (expected NAV_FENCE_POLYGON_VERTEX_INCLUSION/EXCLUSION, NAV_FENCE_CIRCLE_INCLUSION/EXCLUSION"
                        + " or NAV_FENCE_RETURN_POINT)");
            }
            requireInRange(i, it);
            boolean vertex = command == MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION
                    || command == MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION;
            if (!polygon.isEmpty() && (!vertex || command != polygonCommand || it.param1() != polygonSize)) {
                throw new BadItemException(i, "fence item " + i + ": the polygon that starts at item " + polygonStart
                        + " has " + polygon.size() + " of its " + polygonSize + " vertices; found " + it.commandName()
                        + (vertex ? " with a vertex count of " + ItemText.number(it.param1()) : "")
                        + " before its last vertex");
            }
            if (vertex) {
                if (polygon.isEmpty()) {
                    float count = it.param1();
                    if (!(count >= 3) || count != Math.rint(count)) {
                        throw new BadItemException(i, "fence item " + i + ": a polygon vertex's param1 is the polygon's"
                                + " vertex count, at least 3; found " + ItemText.number(count));
                    }
                    polygonCommand = command;
                    polygonSize = (int) count;
                    polygonStart = i;
                }
                polygon.add(horizontal(it));
                if (polygon.size() == polygonSize) {
                    regions.add(new FenceRegion.Polygon(command == MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION,
                            polygon));
                    polygon = new ArrayList<>();
                }
            } else if (command == MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT) {
                if (returnPoint != null) {
                    throw new BadItemException(i, "fence item " + i + ": a second NAV_FENCE_RETURN_POINT (a fence has"
                            + " at most one)");
                }
                returnPoint = it.position();
            } else {
                if (!(it.param1() > 0) || Float.isInfinite(it.param1())) {
                    throw new BadItemException(i, "fence item " + i + ": " + it.commandName() + "'s param1 is its"
                            + " radius in metres, above 0; found " + ItemText.number(it.param1()));
                }
                regions.add(new FenceRegion.Circle(command == MAV_CMD.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION,
                        horizontal(it), it.param1()));
            }
        }
        if (!polygon.isEmpty()) {
            throw new BadItemException(fenceItems.size() - 1, "fence item " + (fenceItems.size() - 1) + ": the polygon"
                    + " that starts at item " + polygonStart + " has " + polygon.size() + " of its " + polygonSize
                    + " vertices: the fence ends before its last vertex");
        }
        return new Fence(items, regions, returnPoint);
    }

    /**
     * The fence of regions and an optional return point, with QGroundControl's items: vertices and
     * circles in MAV_FRAME_GLOBAL at altitude 0 (ArduPilot ignores it and downloads 0), autocontinue
     * off; the return point at its height in the frame given (QGroundControl: GLOBAL_RELATIVE_ALT).
     */
    public static Fence of(List<FenceRegion> regions, Position returnPoint, int returnPointFrame) {
        List<MissionItem> items = new ArrayList<>();
        for (FenceRegion r : regions) {
            if (r instanceof FenceRegion.Polygon p) {
                int command = p.inclusion() ? MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION
                        : MAV_CMD.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION;
                for (Position v : p.vertices()) {
                    items.add(item(items.size(), command, MissionItem.GLOBAL_INT, p.vertices().size(), v, 0));
                }
            }
        }
        for (FenceRegion r : regions) {
            if (r instanceof FenceRegion.Circle c) {
                int command = c.inclusion() ? MAV_CMD.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION
                        : MAV_CMD.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION;
                items.add(item(items.size(), command, MissionItem.GLOBAL_INT, (float) c.radius(), c.center(), 0));
            }
        }
        if (returnPoint != null) {
            items.add(item(items.size(), MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT, returnPointFrame, 0, returnPoint,
                    (float) returnPoint.hae()));
        }
        return of(items);
    }

    private static MissionItem item(int seq, int command, int frame, float p1, Position p, float z) {
        return new MissionItem(seq, command, frame, p1, 0, 0, 0, MissionItem.degE7(p.latitudeDegrees()),
                MissionItem.degE7(p.longitudeDegrees()), z, false);
    }

    /** The items, numbered from 0, as MAV_MISSION_TYPE_FENCE carries them. */
    public List<MissionItem> items() {
        return items;
    }

    public List<FenceRegion> regions() {
        return regions;
    }

    /** Where the vehicle goes on a breach when the fence action is to return there, if the fence says. */
    public Optional<Position> returnPoint() {
        return Optional.ofNullable(returnPoint);
    }

    public boolean isEmpty() {
        return items.isEmpty();
    }

    /**
     * The first region a position breaks (outside an inclusion region, inside an exclusion one), if
     * any. With several inclusion regions ArduPilot requires the vehicle inside all of them.
     */
    public Optional<FenceRegion> breachedBy(Position p) {
        for (FenceRegion r : regions) {
            if (r.contains(p) != r.inclusion()) {
                return Optional.of(r);
            }
        }
        return Optional.empty();
    }

    /** "2 regions (inclusion polygon of 4 vertices, exclusion circle of 50 m), return point". */
    public String describe() {
        if (isEmpty()) {
            return "no fence";
        }
        StringBuilder sb = new StringBuilder().append(regions.size()).append(regions.size() == 1 ? " region" : " regions");
        if (!regions.isEmpty()) {
            sb.append(" (");
            for (int i = 0; i < regions.size(); i++) {
                sb.append(i > 0 ? ", " : "").append(regions.get(i).describe());
            }
            sb.append(')');
        }
        return returnPoint == null ? sb.toString() : sb.append(", return point").toString();
    }

    private static Position horizontal(MissionItem it) {
        return Position.fromDegrees(it.x() * 1e-7, it.y() * 1e-7, 0);
    }

    static void requireInRange(int index, MissionItem it) {
        if (Math.abs((long) it.x()) > 900_000_000L) {
            throw new BadItemException(index, "item " + index + " (" + it.commandName() + "): latitude "
                    + ItemText.degrees(it.x()) + " is out of range (-90 to 90)");
        }
        if (Math.abs((long) it.y()) > 1_800_000_000L) {
            throw new BadItemException(index, "item " + index + " (" + it.commandName() + "): longitude "
                    + ItemText.degrees(it.y()) + " is out of range (-180 to 180)");
        }
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Fence f && f.items.equals(items);
    }

    @Override
    public int hashCode() {
        return items.hashCode();
    }

    @Override
    public String toString() {
        return "Fence[" + describe() + "]";
    }
}
