package dolphin.mission.survey;

import dolphin.core.Position;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Objects;

/**
 * QGroundControl's corridor scan (complexItemType "CorridorScan"): copies of a polyline offset
 * side by side to cover a corridor {@code width} m wide (docs/qgc-surveys.md §3.1).
 */
public final class CorridorScan extends MappingItem {

    private final List<GeoPoint> polyline;
    private final double width;
    private final EntryCorner entry;
    private final TransectOptions options;
    private final List<List<TransectPoint>> transects;
    private final List<TransectPoint> path;

    public CorridorScan(String word, List<Position> polyline, double width, PhotoGrid grid, EntryCorner entry,
                        TransectOptions options) {
        super(word, grid);
        this.polyline = Outlines.checked("corridor polyline", polyline, 2);
        if (!(width >= 0) || Double.isInfinite(width)) {
            throw new IllegalArgumentException("the corridor width must be 0 m (one line along the polyline) or more, got "
                    + Numbers.format(width));
        }
        this.width = width;
        this.entry = Objects.requireNonNull(entry, "entry corner");
        this.options = Objects.requireNonNull(options, "transect options");
        // QGC's corridor has neither (§3.1): refusing beats silently ignoring
        if (options.hoverAndCapture()) {
            throw new IllegalArgumentException("a corridor scan cannot hover and capture; it triggers the camera by distance");
        }
        if (options.refly90()) {
            throw new IllegalArgumentException("a corridor scan has no second pass at 90°; turn refly off");
        }
        this.transects = CorridorTransects.flown(this.polyline, width, grid.spacing(), entry, options).stream()
                .map(List::copyOf).toList();
        this.path = ItemEmitter.flat(transects);
    }

    public List<Position> polyline() {
        return positions(polyline);
    }

    public double width() {
        return width;
    }

    public EntryCorner entry() {
        return entry;
    }

    public TransectOptions options() {
        return options;
    }

    /** The transects in flight order, each with its turnarounds. */
    public List<List<TransectPoint>> transects() {
        return transects;
    }

    @Override
    public List<Position> outline() {
        return polyline();
    }

    @Override
    public boolean closedOutline() {
        return false;
    }

    @Override
    public List<TransectPoint> path() {
        return path;
    }

    /** Photos as QGC counts them for a corridor (§3.1): the path, or the polyline once per transect. */
    @Override
    public Coverage coverage() {
        PhotoGrid g = photoGrid();
        double length = PhotoLayout.length(path);
        double td = g.triggerDistance();
        int photos = td == 0 ? 0 : options.triggerInTurnarounds() ? (int) Math.ceil(length / td)
                : (int) Math.ceil(PhotoLayout.length(polyline.stream().map(p -> p.as(TransectPoint.PointKind.INTERIOR))
                        .toList()) / td) * transects.size();
        return new Coverage(g.gsd(), photos, length);
    }

    @Override
    public List<List<Position>> footprints() {
        return PhotoLayout.footprints(photoGrid(), transects, false);
    }

    @Override
    public List<MissionItem> items(int seq) {
        return ItemEmitter.emit(seq, transects, photoGrid(), options);
    }

    @Override
    public HeightReference heightReference() {
        return options().height();
    }

    @Override
    public double lastHeight() {
        return photoGrid().altitude();
    }

    @Override
    public String qgcType() {
        return "CorridorScan";
    }

    @Override
    public String toString() {
        return name() + ": corridor scan " + Numbers.format(width) + " m wide along a " + polyline.size()
                + "-vertex polyline, " + transects.size() + " transects";
    }
}
