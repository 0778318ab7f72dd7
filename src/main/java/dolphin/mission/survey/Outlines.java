package dolphin.mission.survey;

import dolphin.core.Position;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;

/** Checks on survey outlines, and QGC's polygon and polyline offsets (docs/qgc-surveys.md §3.1, §3.2). */
final class Outlines {

    /** Nearer a pole than this the flat projection degenerates (§6). */
    static final double POLE_MARGIN = 1.0;

    private Outlines() {
    }

    /**
     * The outline's vertices after the checks every mapping item shares: enough vertices, real
     * coordinates, not across the antimeridian, not at a pole.
     *
     * @param what "survey polygon", "corridor polyline", ...
     */
    static List<GeoPoint> checked(String what, List<Position> outline, int minimum) {
        Objects.requireNonNull(outline, what);
        if (outline.size() < minimum) {
            throw new IllegalArgumentException("a " + what + " needs at least " + minimum + " vertices, got " + outline.size());
        }
        List<GeoPoint> out = new ArrayList<>(outline.size());
        double minLon = Double.POSITIVE_INFINITY;
        double maxLon = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < outline.size(); i++) {
            Position p = Objects.requireNonNull(outline.get(i), what + " vertex " + i);
            GeoPoint g = GeoPoint.of(p);
            if (!Double.isFinite(g.lat()) || !Double.isFinite(g.lon()) || Math.abs(g.lat()) > 90 || Math.abs(g.lon()) > 180) {
                throw new IllegalArgumentException("the " + what + "'s vertex " + i + " is not a place on Earth: latitude "
                        + g.lat() + "°, longitude " + g.lon() + "° (expected -90..90 and -180..180)");
            }
            if (Math.abs(g.lat()) > 90 - POLE_MARGIN) {
                throw new IllegalArgumentException("the " + what + "'s vertex " + i + " at latitude " + g.lat()
                        + "° is within " + Numbers.format(POLE_MARGIN) + "° of the " + (g.lat() > 0 ? "North" : "South")
                        + " Pole, where the flat projection QGroundControl uses breaks down; keep surveys below "
                        + Numbers.format(90 - POLE_MARGIN) + "° latitude");
            }
            minLon = Math.min(minLon, g.lon());
            maxLon = Math.max(maxLon, g.lon());
            out.add(g);
        }
        // No real survey spans half the globe: a span over 180° means the outline wraps the other way, across ±180°
        if (maxLon - minLon > 180) {
            throw new IllegalArgumentException("the " + what + " crosses the antimeridian (180° longitude): its longitudes"
                    + " run from " + minLon + "° to " + maxLon + "°; QGroundControl's geometry does not work across it,"
                    + " so split it into two surveys, one each side");
        }
        return Collections.unmodifiableList(out);
    }

    /** The polygon wound clockwise, as QGC's verifyClockwiseWinding leaves it: reversed if it was not. */
    static List<GeoPoint> clockwise(List<GeoPoint> polygon) {
        double sum = 0;
        for (int i = 0; i < polygon.size(); i++) {
            GeoPoint a = polygon.get(i);
            GeoPoint b = polygon.get((i + 1) % polygon.size());
            sum += (b.lon() - a.lon()) * (b.lat() + a.lat());
        }
        if (sum >= 0) {
            return polygon;
        }
        List<GeoPoint> reversed = new ArrayList<>(polygon);
        Collections.reverse(reversed);
        return reversed;
    }

    /**
     * QGCMapPolyline::offsetPolyline: each edge moved {@code d} m to its left (negative: right),
     * bends at the crossing of the neighbouring offset edges (an unlimited mitre), and where those
     * are parallel, the end of the later offset edge, as QGC does.
     */
    static List<GeoPoint> offsetPolyline(List<GeoPoint> line, double d) {
        GeoPoint origin = line.get(0);
        List<Xy> plane = project(origin, line);
        List<Xy[]> edges = new ArrayList<>();
        for (int i = 0; i + 1 < plane.size(); i++) {
            edges.add(offsetEdge(plane.get(i), plane.get(i + 1), d));
        }
        List<GeoPoint> out = new ArrayList<>(line.size());
        out.add(QgcGeo.toGeo(origin, edges.get(0)[0]));
        for (int i = 1; i < edges.size(); i++) {
            Xy[] prev = edges.get(i - 1);
            Xy[] cur = edges.get(i);
            Xy v = QtLine.unboundedIntersection(prev[0], prev[1], cur[0], cur[1]);
            out.add(QgcGeo.toGeo(origin, v == null ? cur[1] : v));
        }
        out.add(QgcGeo.toGeo(origin, edges.get(edges.size() - 1)[1]));
        return out;
    }

    /**
     * QGCMapPolygon::offset: every edge moved {@code d} m to its left (outward for a clockwise
     * polygon), vertex i at the crossing of offset edges i-1 and i; a vertex whose edges are
     * parallel keeps the start of its offset edge.
     */
    static List<GeoPoint> offsetPolygon(List<GeoPoint> polygon, double d) {
        GeoPoint origin = polygon.get(0);
        List<Xy> plane = project(origin, polygon);
        int n = plane.size();
        List<Xy[]> edges = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            edges.add(offsetEdge(plane.get(i), plane.get((i + 1) % n), d));
        }
        List<GeoPoint> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            Xy[] prev = edges.get((i + n - 1) % n);
            Xy[] cur = edges.get(i);
            Xy v = QtLine.unboundedIntersection(prev[0], prev[1], cur[0], cur[1]);
            out.add(QgcGeo.toGeo(origin, v == null ? cur[0] : v));
        }
        return out;
    }

    static List<Xy> project(GeoPoint origin, List<GeoPoint> points) {
        List<Xy> out = new ArrayList<>(points.size());
        for (GeoPoint p : points) {
            out.add(QgcGeo.toPlane(origin, p));
        }
        return out;
    }

    /** The edge p1-p2 moved d to its left, built the way QGC builds it with QLineF. */
    private static Xy[] offsetEdge(Xy p1, Xy p2, double d) {
        Xy start = QtLine.polar(p1, d, QtLine.angle(p1, p2) - 90);
        Xy end = QtLine.polar(p2, d, QtLine.angle(p2, p1) + 90);
        return new Xy[] {start, end};
    }
}
