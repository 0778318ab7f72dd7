package dolphin.mission.survey;

import dolphin.core.Position;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Objects;

/**
 * QGroundControl's survey (complexItemType "survey"): parallel transects across a polygon at a
 * compass angle, flown lawnmower-fashion (docs/qgc-surveys.md §2).
 */
public final class PolygonSurvey extends MappingItem {

    private final List<GeoPoint> polygon;
    private final double angle;
    private final EntryCorner entry;
    private final boolean alternateTransects;
    private final TransectOptions options;
    private final List<List<TransectPoint>> transects;
    private final List<TransectPoint> path;

    /**
     * @param angle the transects' compass heading, degrees (QGC's "angle": 0 = north-south lines)
     * @param alternateTransects fly every other transect, then the rest on the way back (§2.5)
     */
    public PolygonSurvey(String word, List<Position> polygon, PhotoGrid grid, double angle, EntryCorner entry,
                         boolean alternateTransects, TransectOptions options) {
        super(word, grid);
        this.polygon = Outlines.checked("survey polygon", polygon, 3);
        if (!Double.isFinite(angle)) {
            throw new IllegalArgumentException("the survey angle must be a number of degrees, got " + angle);
        }
        this.angle = angle;
        this.entry = Objects.requireNonNull(entry, "entry corner");
        this.alternateTransects = alternateTransects;
        this.options = Objects.requireNonNull(options, "transect options");
        this.transects = SurveyTransects.flown(this.polygon, angle, grid.spacing(), entry, alternateTransects, options,
                grid.triggerDistance()).stream().map(List::copyOf).toList();
        if (transects.isEmpty()) {
            throw new IllegalArgumentException("no transect crosses the survey polygon at an angle of "
                    + Numbers.format(angle) + "°: QGroundControl then tries one line through the middle of the polygon's"
                    + " bounding box, and that misses it too (a C- or L-shaped polygon?); change the angle or the polygon");
        }
        this.path = ItemEmitter.flat(transects);
    }

    /**
     * The angle, in whole degrees from 0 to 179, that needs the fewest transects over the polygon at
     * this spacing; of equal ones the smallest.
     */
    public static double fewestPassesAngle(List<Position> polygon, double spacing) {
        List<GeoPoint> p = Outlines.checked("survey polygon", polygon, 3);
        if (!(spacing > 0) || Double.isInfinite(spacing)) {
            throw new IllegalArgumentException("the transect spacing must be above 0 m, got " + Numbers.format(spacing));
        }
        int best = 0;
        int fewest = Integer.MAX_VALUE;
        for (int a = 0; a < 180; a++) {
            int n = SurveyTransects.pass(p, SurveyTransects.clamp(a), spacing).size();
            if (n > 0 && n < fewest) {
                fewest = n;
                best = a;
            }
        }
        return best;
    }

    public List<Position> polygon() {
        return positions(polygon);
    }

    public double angle() {
        return angle;
    }

    public EntryCorner entry() {
        return entry;
    }

    public boolean alternateTransects() {
        return alternateTransects;
    }

    public TransectOptions options() {
        return options;
    }

    /** The transects in flight order (both passes with refly), each with its turnarounds and hover points. */
    public List<List<TransectPoint>> transects() {
        return transects;
    }

    @Override
    public List<Position> outline() {
        return polygon();
    }

    @Override
    public boolean closedOutline() {
        return true;
    }

    @Override
    public List<TransectPoint> path() {
        return path;
    }

    @Override
    public Coverage coverage() {
        PhotoGrid g = photoGrid();
        double length = PhotoLayout.length(path);
        return new Coverage(g.gsd(), photos(length), length);
    }

    /**
     * QGC's CameraShots (§1.4): with photos in the turnarounds the whole path over the trigger
     * distance, else each camera section's; with hover and capture, the stops.
     */
    private int photos(double pathLength) {
        double td = photoGrid().triggerDistance();
        if (td == 0) {
            return 0;
        }
        if (hoversToShoot()) {
            return PhotoLayout.transectShots(transects, td, true).size();
        }
        if (options.triggerInTurnarounds()) {
            return (int) Math.ceil(pathLength / td);
        }
        int shots = 0;
        for (List<TransectPoint> s : PhotoLayout.sections(transects)) {
            shots += (int) Math.ceil(PhotoLayout.length(s) / td);
        }
        return shots;
    }

    /** Whether the vehicle stops at each photo (hover and capture with photos to take). */
    public boolean hoversToShoot() {
        return options.hoverAndCapture() && photoGrid().triggerDistance() != 0;
    }

    @Override
    public List<List<Position>> footprints() {
        return PhotoLayout.footprints(photoGrid(), transects, hoversToShoot());
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
        return "survey";
    }

    @Override
    public String toString() {
        return name() + ": survey of a " + polygon.size() + "-vertex polygon, " + transects.size() + " transects at "
                + Numbers.format(angle) + "°, " + Numbers.format(photoGrid().spacing()) + " m apart";
    }
}
