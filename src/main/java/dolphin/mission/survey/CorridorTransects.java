package dolphin.mission.survey;

import dolphin.mission.survey.TransectPoint.PointKind;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** The transects of a corridor scan: copies of the polyline offset side by side (docs/qgc-surveys.md §3.1). */
final class CorridorTransects {

    private CorridorTransects() {
    }

    /** How many transects cover a corridor {@code width} m wide at {@code spacing} m. */
    static int count(double width, double spacing) {
        return width > 0 ? (int) Math.ceil(width / effective(spacing)) : 1;
    }

    private static double effective(double spacing) {
        return spacing < SurveyTransects.MIN_SPACING ? SurveyTransects.FORCED_SPACING : spacing;
    }

    static List<List<TransectPoint>> flown(List<GeoPoint> polyline, double width, double spacing, EntryCorner entry,
                                           TransectOptions options) {
        double s = effective(spacing);
        int n = count(width, spacing);
        List<List<TransectPoint>> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            double offset = n == 1 ? 0 : width / 2 - s / 2 - i * s;
            out.add(transect(Outlines.offsetPolyline(polyline, offset), options.turnaround()));
        }
        if (entry.reversesOrder()) {
            Collections.reverse(out);
        }
        if (entry.reversesPoints()) {
            // the transects start at the other end, so that end is where the camera section starts
            // (the corpus has only entry 0: unverified against QGC output)
            out.replaceAll(t -> swapped(reversed(t)));
        }
        // only the current generation relabels the reversed (odd) transects so that entry stays first
        boolean swap = options.emission() == Emission.CURRENT;
        for (int i = 1; i < out.size(); i += 2) {
            List<TransectPoint> r = reversed(out.get(i));
            out.set(i, swap ? swapped(r) : r);
        }
        return out;
    }

    /** Entry, bends, exit; the turnarounds continue the first and last legs outwards. */
    private static List<TransectPoint> transect(List<GeoPoint> line, double turnaround) {
        List<TransectPoint> t = new ArrayList<>(line.size() + 2);
        int last = line.size() - 1;
        if (turnaround > 0) {
            t.add(QgcGeo.destination(line.get(0), -turnaround, QgcGeo.azimuth(line.get(0), line.get(1)))
                    .as(PointKind.TURNAROUND));
        }
        t.add(line.get(0).as(PointKind.ENTRY));
        for (int i = 1; i < last; i++) {
            t.add(line.get(i).as(PointKind.INTERIOR));
        }
        t.add(line.get(last).as(PointKind.EXIT));
        if (turnaround > 0) {
            t.add(QgcGeo.destination(line.get(last), -turnaround, QgcGeo.azimuth(line.get(last), line.get(last - 1)))
                    .as(PointKind.TURNAROUND));
        }
        return t;
    }

    private static List<TransectPoint> reversed(List<TransectPoint> t) {
        List<TransectPoint> r = new ArrayList<>(t);
        Collections.reverse(r);
        return r;
    }

    private static List<TransectPoint> swapped(List<TransectPoint> t) {
        List<TransectPoint> out = new ArrayList<>(t.size());
        for (TransectPoint p : t) {
            out.add(switch (p.kind()) {
                case ENTRY -> p.withKind(PointKind.EXIT);
                case EXIT -> p.withKind(PointKind.ENTRY);
                default -> p;
            });
        }
        return out;
    }
}
