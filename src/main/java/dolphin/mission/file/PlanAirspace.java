package dolphin.mission.file;

import dolphin.mission.model.ItemText;
import dolphin.mission.model.BadItemException;
import dolphin.mission.model.Fence;
import dolphin.mission.model.FenceRegion;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.RallyPoints;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.core.Position;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

/**
 * A plan's {@code geoFence} and {@code rallyPoints}, both ways, as QGroundControl's
 * GeoFenceController and RallyPointController read and write them:
 * {@code "geoFence": {"version": 2, "polygons": [{"version": 1, "inclusion": true, "polygon": [[lat, lon], ...]}],
 * "circles": [{"version": 1, "inclusion": false, "circle": {"center": [lat, lon], "radius": r}}],
 * "breachReturn": [lat, lon, alt]}} and {@code "rallyPoints": {"version": 2, "points": [[lat, lon, alt], ...]}}.
 * Version 1 of either (or none) is ignored, as QGroundControl does; other versions are refused.
 *
 * <p>Heights of the return point and rally points are above home in a plan (QGroundControl sends
 * them in MAV_FRAME_GLOBAL_RELATIVE_ALT). Writing points of another frame converts heights above
 * mean sea level with the plan's home; a point above terrain cannot be written.
 */
final class PlanAirspace {

    static final int FENCE_VERSION = 2;
    static final int RALLY_VERSION = 2;
    static final int REGION_VERSION = 1;

    private PlanAirspace() {
    }

    static Fence readFence(Object value) {
        if (value == null) {
            return Fence.NONE;
        }
        Map<?, ?> json = PlanJson.map(value, "geoFence");
        Object v = json.get("version");
        if (v == null || PlanJson.version(v, "geoFence.version") == 1) {
            return Fence.NONE;
        }
        if (PlanJson.version(v, "geoFence.version") != FENCE_VERSION) {
            throw new IllegalArgumentException("geoFence.version " + v + " is not one QGroundControl reads (" + FENCE_VERSION
                    + "; version 1 is ignored)");
        }
        List<FenceRegion> regions = new ArrayList<>();
        List<?> polygons = PlanJson.list(json.get("polygons"), "geoFence.polygons");
        for (int i = 0; i < polygons.size(); i++) {
            String where = "geoFence.polygons[" + i + "]";
            Map<?, ?> p = region(polygons.get(i), where);
            List<?> path = PlanJson.list(p.get("polygon"), where + ".polygon");
            List<Position> vertices = new ArrayList<>();
            for (int k = 0; k < path.size(); k++) {
                vertices.add(position(path.get(k), false, where + ".polygon[" + k + "]"));
            }
            if (vertices.size() < 3) {
                throw new IllegalArgumentException(where + ".polygon: a fence polygon needs at least 3 vertices, found "
                        + vertices.size());
            }
            regions.add(new FenceRegion.Polygon(PlanJson.bool(p.get("inclusion"), where + ".inclusion"), vertices));
        }
        List<?> circles = PlanJson.list(json.get("circles"), "geoFence.circles");
        for (int i = 0; i < circles.size(); i++) {
            String where = "geoFence.circles[" + i + "]";
            Map<?, ?> c = region(circles.get(i), where);
            Map<?, ?> circle = PlanJson.map(c.get("circle"), where + ".circle");
            double radius = PlanJson.toDouble(circle.get("radius"), where + ".circle.radius");
            if (!(radius > 0)) {
                throw new IllegalArgumentException(where + ".circle.radius: a fence circle's radius is above 0 m, found "
                        + radius);
            }
            regions.add(new FenceRegion.Circle(PlanJson.bool(c.get("inclusion"), where + ".inclusion"),
                    position(circle.get("center"), false, where + ".circle.center"), radius));
        }
        Position returnPoint = json.get("breachReturn") == null ? null
                : position(json.get("breachReturn"), true, "geoFence.breachReturn");
        return Fence.of(regions, returnPoint, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT);
    }

    static RallyPoints readRally(Object value) {
        if (value == null) {
            return RallyPoints.NONE;
        }
        Map<?, ?> json = PlanJson.map(value, "rallyPoints");
        Object v = json.get("version");
        if (v != null && PlanJson.version(v, "rallyPoints.version") == 1) {
            return RallyPoints.NONE;
        }
        if (v == null || PlanJson.version(v, "rallyPoints.version") != RALLY_VERSION) {
            throw new IllegalArgumentException("rallyPoints.version " + v + " is not one QGroundControl reads ("
                    + RALLY_VERSION + "; version 1 is ignored)");
        }
        List<?> points = PlanJson.list(json.get("points"), "rallyPoints.points");
        List<MissionItem> items = new ArrayList<>();
        for (int i = 0; i < points.size(); i++) {
            String where = "rallyPoints.points[" + i + "]";
            List<?> c = coordinate(points.get(i), true, where);
            items.add(new MissionItem(i, com.MAVLink.enums.MAV_CMD.MAV_CMD_NAV_RALLY_POINT,
                    MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0, 0, PlanJson.degE7(c.get(0), 90, where + "[0]"),
                    PlanJson.degE7(c.get(1), 180, where + "[1]"), PlanJson.toFloat(c.get(2), where + "[2]"), false));
        }
        try {
            return RallyPoints.of(items);
        } catch (BadItemException e) {
            throw new IllegalArgumentException("rallyPoints.points[" + e.index() + "]: " + e.getMessage(), e);
        }
    }

    /** The plan's geoFence; heights above mean sea level become heights above {@code home}. */
    static Map<String, Object> writeFence(Fence fence, MissionItem home) {
        List<Object> polygons = new ArrayList<>();
        List<Object> circles = new ArrayList<>();
        for (FenceRegion r : fence.regions()) {
            if (r instanceof FenceRegion.Polygon p) {
                List<Object> path = new ArrayList<>();
                for (Position v : p.vertices()) {
                    path.add(latLon(v));
                }
                polygons.add(FileValues.ordered("version", REGION_VERSION, "inclusion", p.inclusion(), "polygon", path));
            } else if (r instanceof FenceRegion.Circle c) {
                circles.add(FileValues.ordered("version", REGION_VERSION, "inclusion", c.inclusion(), "circle",
                        FileValues.ordered("center", latLon(c.center()), "radius", FileValues.jsonNumber((float) c.radius()))));
            }
        }
        Map<String, Object> json = FileValues.ordered("version", FENCE_VERSION, "polygons", polygons, "circles", circles);
        fence.items().stream().filter(it -> it.command() == com.MAVLink.enums.MAV_CMD.MAV_CMD_NAV_FENCE_RETURN_POINT)
                .findFirst().ifPresent(it -> json.put("breachReturn", Arrays.asList(FileValues.jsonDegrees(it.x()),
                        FileValues.jsonDegrees(it.y()), FileValues.jsonNumber(aboveHome(it, home, "the fence's return point")))));
        return json;
    }

    static Map<String, Object> writeRally(RallyPoints rally, MissionItem home) {
        List<Object> points = new ArrayList<>();
        for (MissionItem it : rally.items()) {
            points.add(Arrays.asList(FileValues.jsonDegrees(it.x()), FileValues.jsonDegrees(it.y()),
                    FileValues.jsonNumber(aboveHome(it, home, "rally point " + it.seq()))));
        }
        return FileValues.ordered("version", RALLY_VERSION, "points", points);
    }

    /** An item's height above home: a plan has no other frame for these points. */
    private static float aboveHome(MissionItem it, MissionItem home, String what) {
        return switch (MissionItem.altitudeReference(it.frame())) {
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT -> it.z();
            case MAV_FRAME.MAV_FRAME_GLOBAL -> it.z() - home.z();
            default -> throw new IllegalArgumentException(what + " is in frame " + it.frameName()
                    + ": a QGroundControl plan keeps its height above home only");
        };
    }

    private static List<Object> latLon(Position p) {
        return Arrays.asList(FileValues.jsonDegrees(MissionItem.degE7(p.latitudeDegrees())),
                FileValues.jsonDegrees(MissionItem.degE7(p.longitudeDegrees())));
    }

    private static Map<?, ?> region(Object value, String where) {
        Map<?, ?> r = PlanJson.map(value, where);
        double v = PlanJson.version(r.get("version"), where + ".version");
        if (v != REGION_VERSION) {
            throw new IllegalArgumentException(where + ".version " + ItemText.number((float) v)
                    + " is not one QGroundControl reads (" + REGION_VERSION + ")");
        }
        return r;
    }

    private static Position position(Object value, boolean altitude, String where) {
        List<?> c = coordinate(value, altitude, where);
        int lat = PlanJson.degE7(c.get(0), 90, where + "[0]");
        int lon = PlanJson.degE7(c.get(1), 180, where + "[1]");
        return Position.fromDegrees(lat * 1e-7, lon * 1e-7, altitude ? PlanJson.toFloat(c.get(2), where + "[2]") : 0);
    }

    private static List<?> coordinate(Object value, boolean altitude, String where) {
        List<?> c = PlanJson.list(value, where);
        int n = altitude ? 3 : 2;
        if (c.size() != n) {
            throw new IllegalArgumentException(where + ": expected " + (altitude ? "[lat, lon, alt]" : "[lat, lon]")
                    + ", found " + c.size() + " values");
        }
        return c;
    }
}
