package dolphin.web;

import dolphin.core.Position;
import java.util.ArrayList;
import java.util.List;

/**
 * Where a vehicle has been: a point each time it has moved {@value #STEP_METRES} m from the last
 * one; at {@value #MAX_POINTS} points every other point is dropped, so a long flight keeps its
 * whole shape in bounded memory.
 */
final class Track {

    static final double STEP_METRES = 2;
    static final int MAX_POINTS = 500;

    private final List<Position> points = new ArrayList<>();

    void add(Position p) {
        if (!points.isEmpty() && points.get(points.size() - 1).horizontalDistanceTo(p) < STEP_METRES) {
            return;
        }
        points.add(p);
        if (points.size() >= MAX_POINTS) {
            List<Position> kept = new ArrayList<>(MAX_POINTS / 2 + 1);
            for (int i = 0; i < points.size(); i += 2) {
                kept.add(points.get(i));
            }
            kept.add(points.get(points.size() - 1));
            points.clear();
            points.addAll(kept);
        }
    }

    int size() {
        return points.size();
    }

    /** [[latitude, longitude], ...] in degrees. */
    List<Object> points() {
        List<Object> list = new ArrayList<>(points.size());
        for (Position p : points) {
            list.add(List.of(Math.round(p.latitudeDegrees() * 1e7) / 1e7, Math.round(p.longitudeDegrees() * 1e7) / 1e7));
        }
        return list;
    }
}
