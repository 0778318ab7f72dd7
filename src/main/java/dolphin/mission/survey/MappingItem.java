package dolphin.mission.survey;

import dolphin.core.Position;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionPoint;
import java.util.List;
import java.util.Objects;

/**
 * A QGroundControl complex item: a mission point whose items are generated from an outline and a
 * photo grid (docs/qgc-surveys.md). It has no position of its own.
 */
public abstract sealed class MappingItem extends MissionPoint permits PolygonSurvey, CorridorScan, StructureScan {

    private final PhotoGrid grid;

    MappingItem(String word, PhotoGrid grid) {
        super(word, null);
        this.grid = Objects.requireNonNull(grid, "photo grid");
    }

    /** The polygon (not closed) or polyline vertices, heights 0. */
    public abstract List<Position> outline();

    /** True for polygons. */
    public abstract boolean closedOutline();

    /** Every coordinate flown, in order, with its role: QGC's VisualTransectPoints. */
    public abstract List<TransectPoint> path();

    public PhotoGrid photoGrid() {
        return grid;
    }

    public abstract Coverage coverage();

    /** Each photo's ground rectangle (4 corners), in flight order; empty when manual or not triggering. */
    public abstract List<List<Position>> footprints();

    @Override
    public abstract List<MissionItem> items(int seq);

    /** What the items' heights are measured from. */
    public abstract HeightReference heightReference();

    /** The height of the last waypoint, measured from {@link #heightReference()}: where the vehicle is when the item ends. */
    public abstract double lastHeight();

    /** QGC's complexItemType: "survey", "CorridorScan" or "StructureScan". */
    public abstract String qgcType();

    static List<Position> positions(List<GeoPoint> points) {
        return points.stream().map(GeoPoint::position).toList();
    }
}
