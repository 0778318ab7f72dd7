package dolphin.mission.survey;

import dolphin.mission.survey.TransectPoint.PointKind;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** The transects of a polygon survey, QGroundControl's way (docs/qgc-surveys.md §2.2 to §2.6). */
final class SurveyTransects {

    /** Below this spacing QGC flies a single transect (§2.2 step 3, the corridor's constants). */
    static final double MIN_SPACING = 0.5;
    static final double FORCED_SPACING = 100_000;
    /** How far past the bounding box the grid lines reach, each way together (§2.2 step 6). */
    private static final double GRID_MARGIN = 2000;

    private SurveyTransects() {
    }

    /** The angle clamped once into about ±90°: 340 becomes 160, not -20 (§0.3, §2.2 step 4). */
    static double clamp(double angle) {
        if (angle > 90) {
            return angle - 180;
        }
        return angle < -90 ? angle + 180 : angle;
    }

    /**
     * One pass of transects, each a {p1, p2} pair in flight direction before entry handling
     * (§2.2): a grid of lines at {@code gridAngle} (compass heading) clipped to the polygon from
     * its first to its last crossing.
     */
    static List<GeoPoint[]> pass(List<GeoPoint> polygon, double gridAngle, double spacing) {
        GeoPoint origin = polygon.get(0);
        List<Xy> ring = new ArrayList<>(Outlines.project(origin, polygon));
        ring.add(ring.get(0));
        double minX = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (Xy p : ring) {
            minX = Math.min(minX, p.x());
            maxX = Math.max(maxX, p.x());
            minY = Math.min(minY, p.y());
            maxY = Math.max(maxY, p.y());
        }
        Xy centre = new Xy((minX + maxX) / 2, (minY + maxY) / 2);
        double step = spacing < MIN_SPACING ? FORCED_SPACING : spacing;
        double width = Math.max(maxX - minX, maxY - minY) + GRID_MARGIN;
        double half = width / 2;
        List<Xy[]> lines = new ArrayList<>();
        // QGC's grid phase: from centre - half, not half a spacing inside the polygon (§0.2)
        for (double x = centre.x() - half; x < centre.x() - half + width; x += step) {
            lines.add(new Xy[] {rotate(new Xy(x, centre.y() - half), centre, gridAngle),
                    rotate(new Xy(x, centre.y() + half), centre, gridAngle)});
        }
        List<Xy[]> clipped = new ArrayList<>();
        for (Xy[] line : lines) {
            Xy[] t = clip(line, ring);
            if (t != null) {
                clipped.add(t);
            }
        }
        if (clipped.size() < 2) {
            // fewer than two lines hit: one line through the bounding box centre instead (§0.4)
            Xy[] first = lines.get(0);
            double dx = centre.x() - (first[0].x() + first[1].x()) / 2;
            double dy = centre.y() - (first[0].y() + first[1].y()) / 2;
            Xy[] t = clip(new Xy[] {first[0].plus(dx, dy), first[1].plus(dx, dy)}, ring);
            clipped = t == null ? List.of() : List.<Xy[]>of(t);
        }
        List<GeoPoint[]> out = new ArrayList<>(clipped.size());
        double firstAngle = clipped.isEmpty() ? 0 : QtLine.angle(clipped.get(0)[0], clipped.get(0)[1]);
        for (Xy[] t : clipped) {
            // all transects point the way of the first; no wrap-around handling, as in QGC (§2.2 step 9)
            boolean flip = Math.abs(QtLine.angle(t[0], t[1]) - firstAngle) > 1.0;
            Xy a = flip ? t[1] : t[0];
            Xy b = flip ? t[0] : t[1];
            out.add(new GeoPoint[] {QgcGeo.toGeo(origin, a), QgcGeo.toGeo(origin, b)});
        }
        return out;
    }

    /** QGC's _rotatePoint: clockwise by {@code angle} degrees about {@code centre} in the x-east/y-north plane. */
    private static Xy rotate(Xy p, Xy centre, double angle) {
        double r = Math.toRadians(-angle);
        double dx = p.x() - centre.x();
        double dy = p.y() - centre.y();
        return new Xy(dx * Math.cos(r) - dy * Math.sin(r) + centre.x(), dx * Math.sin(r) + dy * Math.cos(r) + centre.y());
    }

    /** The line from its first to its last crossing of the ring (the pair farthest apart), or null (§2.2 step 7). */
    private static Xy[] clip(Xy[] line, List<Xy> ring) {
        List<Xy> hits = new ArrayList<>();
        for (int j = 0; j + 1 < ring.size(); j++) {
            Xy p = QtLine.boundedIntersection(line[0], line[1], ring.get(j), ring.get(j + 1));
            if (p != null && hits.stream().noneMatch(h -> QtLine.fuzzyEqual(h, p))) {
                hits.add(p);
            }
        }
        if (hits.size() < 2) {
            return null;
        }
        Xy[] best = null;
        double bestDistance = 0;
        for (Xy a : hits) {
            for (Xy b : hits) {
                double d = a.distanceTo(b);
                if (d > bestDistance) {
                    bestDistance = d;
                    best = new Xy[] {a, b};
                }
            }
        }
        return best;
    }

    /**
     * Every transect flown, in order, as its points: both passes when refly is on, entry corner,
     * alternate order, lawnmower, hover points and turnarounds applied (§2.3 to §2.6).
     */
    static List<List<TransectPoint>> flown(List<GeoPoint> polygon, double angle, double spacing, EntryCorner entry,
                                           boolean alternate, TransectOptions options, double triggerDistance) {
        double gridAngle = clamp(angle);
        List<List<TransectPoint>> first = finish(entered(pass(polygon, gridAngle, spacing), entry), alternate, options,
                triggerDistance);
        if (!options.refly90() || first.isEmpty()) {
            return first;
        }
        List<TransectPoint> last = first.get(first.size() - 1);
        List<List<GeoPoint>> second = nearest(entered(pass(polygon, gridAngle + 90, spacing), entry),
                last.get(last.size() - 1).geo());
        List<List<TransectPoint>> all = new ArrayList<>(first);
        all.addAll(finish(second, alternate, options, triggerDistance));
        return all;
    }

    /** §2.3: Bottom* reverses each transect, *Right the order of the transects. */
    private static List<List<GeoPoint>> entered(List<GeoPoint[]> pass, EntryCorner entry) {
        List<List<GeoPoint>> out = new ArrayList<>();
        for (GeoPoint[] t : pass) {
            out.add(entry.reversesPoints() ? List.of(t[1], t[0]) : List.of(t[0], t[1]));
        }
        if (entry.reversesOrder()) {
            Collections.reverse(out);
        }
        return out;
    }

    /**
     * The refly pass turned to start near where the first pass ended (§2.4); like QGC's
     * _optimizeTransectsForShortestDistance, only three of the four candidate starts compete.
     */
    private static List<List<GeoPoint>> nearest(List<List<GeoPoint>> pass, GeoPoint from) {
        if (pass.isEmpty()) {
            return pass;
        }
        List<GeoPoint> head = pass.get(0);
        List<GeoPoint> tail = pass.get(pass.size() - 1);
        double[] d = {QgcGeo.distance(head.get(0), from), QgcGeo.distance(head.get(head.size() - 1), from),
                QgcGeo.distance(tail.get(0), from), QgcGeo.distance(tail.get(tail.size() - 1), from)};
        int best = 0;
        for (int i = 1; i < 3; i++) {
            if (d[i] < d[best]) {
                best = i;
            }
        }
        List<List<GeoPoint>> out = new ArrayList<>(pass);
        if (best == 2) {
            Collections.reverse(out);
        }
        if (best == 1) {
            out.replaceAll(SurveyTransects::reversed);
        }
        return out;
    }

    /** §2.5, §2.6: alternate order, lawnmower, then each transect's points. */
    private static List<List<TransectPoint>> finish(List<List<GeoPoint>> pass, boolean alternate, TransectOptions options,
                                                    double triggerDistance) {
        List<List<GeoPoint>> ordered = alternate ? alternated(pass) : pass;
        List<List<TransectPoint>> out = new ArrayList<>(ordered.size());
        for (int i = 0; i < ordered.size(); i++) {
            List<GeoPoint> t = i % 2 == 1 ? reversed(ordered.get(i)) : ordered.get(i);
            out.add(points(t.get(0), t.get(1), options, triggerDistance));
        }
        return out;
    }

    /** Indices 0, 2, 4, ... then the odd ones backwards: ..., 5, 3, 1 (§2.5). */
    static <T> List<T> alternated(List<T> pass) {
        List<T> out = new ArrayList<>(pass.size());
        for (int i = 0; i < pass.size(); i += 2) {
            out.add(pass.get(i));
        }
        for (int i = pass.size() - 1; i > 0; i--) {
            if (i % 2 == 1) {
                out.add(pass.get(i));
            }
        }
        return out;
    }

    private static List<GeoPoint> reversed(List<GeoPoint> t) {
        List<GeoPoint> r = new ArrayList<>(t);
        Collections.reverse(r);
        return r;
    }

    /** Entry, hover stops, exit, framed by the turnarounds (§2.6). */
    private static List<TransectPoint> points(GeoPoint entry, GeoPoint exit, TransectOptions options,
                                              double triggerDistance) {
        List<TransectPoint> out = new ArrayList<>();
        double t = options.turnaround();
        if (t > 0) {
            out.add(QgcGeo.destination(entry, -t, QgcGeo.azimuth(entry, exit)).as(PointKind.TURNAROUND));
        }
        out.add(entry.as(PointKind.ENTRY));
        if (options.hoverAndCapture() && triggerDistance != 0) {
            double length = QgcGeo.distance(entry, exit);
            double azimuth = QgcGeo.azimuth(entry, exit);
            if (triggerDistance < length) {
                int n = (int) Math.floor(length / triggerDistance);
                for (int k = 1; k <= n; k++) {
                    out.add(QgcGeo.destination(entry, k * triggerDistance, azimuth).as(PointKind.HOVER));
                }
            }
        }
        out.add(exit.as(PointKind.EXIT));
        if (t > 0) {
            out.add(QgcGeo.destination(exit, -t, QgcGeo.azimuth(exit, entry)).as(PointKind.TURNAROUND));
        }
        return out;
    }
}
