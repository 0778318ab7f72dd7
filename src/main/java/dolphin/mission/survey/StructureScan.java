package dolphin.mission.survey;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.core.Position;
import dolphin.mission.model.MissionItem;
import dolphin.mission.survey.TransectPoint.PointKind;
import java.util.ArrayList;
import java.util.List;

/**
 * QGroundControl's structure scan (complexItemType "StructureScan", docs/qgc-surveys.md §3.2):
 * rings round a structure at {@code grid.altitude()} m from its walls, one per layer. The photo
 * grid's trigger distance (QGC's frontal footprint) is the layer height and its spacing (the side
 * footprint) the distance between photos along a ring.
 */
public final class StructureScan extends MappingItem {

    private final List<GeoPoint> polygon;
    private final List<GeoPoint> ring;
    private final double structureHeight;
    private final double scanBottom;
    private final double entranceAltitude;
    private final boolean startFromTop;
    private final double gimbalPitch;
    private final int layers;
    private final List<TransectPoint> path;

    /**
     * @param polygon the structure's footprint, wound clockwise first (QGC does when it is drawn);
     *                the scan enters at vertex 0
     * @param structureHeight the top of the structure, m above home
     * @param scanBottom the lowest altitude scanned, m above home
     * @param entranceAltitude the altitude of the first and last waypoint, m above home
     * @param gimbalPitch the camera pitch, degrees (QGC forces 0 with a camera)
     */
    public StructureScan(String word, List<Position> polygon, PhotoGrid grid, double structureHeight, double scanBottom,
                         double entranceAltitude, boolean startFromTop, double gimbalPitch) {
        super(word, grid);
        this.polygon = Outlines.clockwise(Outlines.checked("structure polygon", polygon, 3));
        finite("structure height", structureHeight);
        finite("scan bottom", scanBottom);
        finite("entrance altitude", entranceAltitude);
        if (!Double.isFinite(gimbalPitch)) {
            throw new IllegalArgumentException("the gimbal pitch must be a number of degrees, got " + gimbalPitch);
        }
        if (scanBottom > structureHeight) {
            throw new IllegalArgumentException("the scan bottom (" + Numbers.format(scanBottom)
                    + " m) is above the structure height (" + Numbers.format(structureHeight)
                    + " m); the bottom must be at or below the top");
        }
        if (grid.triggerDistance() <= 0) {
            throw new IllegalArgumentException("a structure scan needs a layer height (the photo grid's trigger distance)"
                    + " above 0 m, got " + Numbers.format(grid.triggerDistance()));
        }
        this.structureHeight = structureHeight;
        this.scanBottom = scanBottom;
        this.entranceAltitude = entranceAltitude;
        this.startFromTop = startFromTop;
        this.gimbalPitch = gimbalPitch;
        this.ring = Outlines.offsetPolygon(this.polygon, grid.altitude());
        this.layers = Math.max((int) Math.ceil(Math.max(structureHeight - scanBottom, 0) / grid.triggerDistance()), 1);
        this.path = List.copyOf(buildPath());
    }

    private static void finite(String what, double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException("the " + what + " must be a number of metres, got " + v);
        }
    }

    private List<TransectPoint> buildPath() {
        List<TransectPoint> out = new ArrayList<>();
        out.add(ring.get(0).as(PointKind.TURNAROUND));
        for (int layer = 0; layer < layers; layer++) {
            for (int i = 0; i <= ring.size(); i++) {
                PointKind kind = i == 0 ? PointKind.ENTRY : i == ring.size() ? PointKind.EXIT : PointKind.INTERIOR;
                out.add(ring.get(i % ring.size()).as(kind));
            }
        }
        out.add(ring.get(0).as(PointKind.TURNAROUND));
        return out;
    }

    public List<Position> polygon() {
        return positions(polygon);
    }

    /** The ring flown: the polygon offset outwards by the distance from the structure. */
    public List<Position> flightPolygon() {
        return positions(ring);
    }

    public double structureHeight() {
        return structureHeight;
    }

    public double scanBottom() {
        return scanBottom;
    }

    public double entranceAltitude() {
        return entranceAltitude;
    }

    public boolean startFromTop() {
        return startFromTop;
    }

    public double gimbalPitch() {
        return gimbalPitch;
    }

    /** max(ceil((height - bottom) / layer height), 1), as QGC recomputes it on every change. */
    public int layers() {
        return layers;
    }

    /** The altitude of layer k (0 = the first flown), m above home: half a layer inside the scanned band. */
    public double layerAltitude(int k) {
        if (k < 0 || k >= layers) {
            throw new IllegalArgumentException("layer " + k + " does not exist: this scan has layers 0 to " + (layers - 1));
        }
        double h = photoGrid().triggerDistance();
        return startFromTop ? structureHeight - h / 2 - k * h : scanBottom + h / 2 + k * h;
    }

    @Override
    public List<Position> outline() {
        return polygon();
    }

    @Override
    public boolean closedOutline() {
        return true;
    }

    /** The entrance, each layer's ring closed at its start vertex, the entrance again. */
    @Override
    public List<TransectPoint> path() {
        return path;
    }

    /** Photos every {@code grid.spacing()} m round each ring; path length horizontal only. */
    @Override
    public Coverage coverage() {
        double ringLength = PhotoLayout.length(closedRing());
        int photos = (int) Math.ceil(ringLength / photoGrid().spacing()) * layers;
        return new Coverage(photoGrid().gsd(), photos, PhotoLayout.length(path));
    }

    private List<TransectPoint> closedRing() {
        List<TransectPoint> closed = new ArrayList<>();
        for (int i = 0; i <= ring.size(); i++) {
            closed.add(ring.get(i % ring.size()).as(PointKind.INTERIOR));
        }
        return closed;
    }

    /**
     * Each photo's patch of wall: footprintSide wide along the wall, footprintFrontal high, centred
     * at the layer altitude on the structure facing the photo point (corners top-left, top-right,
     * bottom-right, bottom-left as seen from the ring).
     */
    @Override
    public List<List<Position>> footprints() {
        PhotoGrid g = photoGrid();
        if (g.manual()) {
            return List.of();
        }
        List<PhotoLayout.Shot> shots = PhotoLayout.along(closedRing(), g.spacing());
        List<List<Position>> out = new ArrayList<>();
        for (int layer = 0; layer < layers; layer++) {
            double alt = layerAltitude(layer);
            for (PhotoLayout.Shot s : shots) {
                // clockwise ring: the structure is to the right of the direction of flight
                GeoPoint wall = QgcGeo.destination(s.centre(), g.altitude(), s.heading() + 90);
                GeoPoint left = QgcGeo.destination(wall, -g.footprintSide() / 2, s.heading());
                GeoPoint right = QgcGeo.destination(wall, g.footprintSide() / 2, s.heading());
                double top = alt + g.footprintFrontal() / 2;
                double bottom = alt - g.footprintFrontal() / 2;
                out.add(List.of(Position.fromDegrees(left.lat(), left.lon(), top),
                        Position.fromDegrees(right.lat(), right.lon(), top),
                        Position.fromDegrees(right.lat(), right.lon(), bottom),
                        Position.fromDegrees(left.lat(), left.lon(), bottom)));
            }
        }
        return out;
    }

    /** §3.2: entrance, region of interest, per layer a closed ring with the trigger on round it, ROI off, entrance. */
    @Override
    public List<MissionItem> items(int seq) {
        List<MissionItem> out = new ArrayList<>();
        GeoPoint entrance = ring.get(0);
        out.add(waypoint(seq++, entrance, entranceAltitude));
        // QGC's DO_SET_ROI_WPNEXT_OFFSET is one ArduPilot refuses at upload (docs/decisions.md, "Camera triggers on
        // ArduPilot"): the camera faces the structure's centre at mid-height instead, ArduPilot's way
        GeoPoint centre = centre(polygon);
        out.add(new MissionItem(seq++, MAV_CMD.MAV_CMD_DO_SET_ROI_LOCATION, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                0, 0, 0, 0, MissionItem.degE7(centre.lat()), MissionItem.degE7(centre.lon()),
                (float) ((scanBottom + structureHeight) / 2), true));
        float trigger = (float) photoGrid().spacing();
        for (int layer = 0; layer < layers; layer++) {
            double alt = layerAltitude(layer);
            for (int i = 0; i <= ring.size(); i++) {
                out.add(waypoint(seq++, ring.get(i % ring.size()), alt));
                if (i == 0) {
                    out.add(MissionItem.command(seq++, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, trigger, 0, 1, 0));
                }
            }
            out.add(MissionItem.command(seq++, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, 0, 0, 0, 0));
        }
        out.add(MissionItem.command(seq++, MAV_CMD.MAV_CMD_DO_SET_ROI_NONE, 0, 0, 0, 0));
        out.add(waypoint(seq, entrance, entranceAltitude));
        return List.copyOf(out);
    }

    /** The mean of the footprint's vertices: inside any building a structure scan goes round. */
    private static GeoPoint centre(List<GeoPoint> polygon) {
        double lat = 0;
        double lon = 0;
        for (GeoPoint p : polygon) {
            lat += p.lat();
            lon += p.lon();
        }
        return new GeoPoint(lat / polygon.size(), lon / polygon.size());
    }

    /** Waypoints above home whatever the grid says, as QGC emits them (§3.2). */
    private static MissionItem waypoint(int seq, GeoPoint p, double altitude) {
        return new MissionItem(seq, MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0,
                Float.NaN, MissionItem.degE7(p.lat()), MissionItem.degE7(p.lon()), (float) altitude, true);
    }

    @Override
    public HeightReference heightReference() {
        return HeightReference.ABOVE_HOME;
    }

    @Override
    public double lastHeight() {
        return entranceAltitude();
    }

    @Override
    public String qgcType() {
        return "StructureScan";
    }

    @Override
    public String toString() {
        return name() + ": structure scan round a " + polygon.size() + "-vertex polygon, " + layers + " layers from "
                + Numbers.format(scanBottom) + " to " + Numbers.format(structureHeight) + " m";
    }
}
