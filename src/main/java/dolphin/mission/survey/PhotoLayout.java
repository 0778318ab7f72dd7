package dolphin.mission.survey;

import dolphin.core.Position;
import dolphin.mission.survey.TransectPoint.PointKind;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** Where the photos of a mapping item are taken, what each covers, and how long its path is. */
final class PhotoLayout {

    /** A photo centre and the heading it is taken on, degrees. */
    record Shot(GeoPoint centre, double heading) {
    }

    private PhotoLayout() {
    }

    /** Σ great-circle legs, metres. */
    static double length(List<TransectPoint> path) {
        double sum = 0;
        for (int i = 1; i < path.size(); i++) {
            sum += QgcGeo.distance(path.get(i - 1).geo(), path.get(i).geo());
        }
        return sum;
    }

    /**
     * Each transect's camera section, from its entry to its exit (walked backwards when a corridor
     * of the no-label-swap generation has the exit first).
     */
    static List<List<TransectPoint>> sections(List<List<TransectPoint>> transects) {
        List<List<TransectPoint>> out = new ArrayList<>(transects.size());
        for (List<TransectPoint> t : transects) {
            int entry = -1;
            int exit = -1;
            for (int i = 0; i < t.size(); i++) {
                if (t.get(i).kind() == PointKind.ENTRY) {
                    entry = i;
                } else if (t.get(i).kind() == PointKind.EXIT) {
                    exit = i;
                }
            }
            List<TransectPoint> s = new ArrayList<>(t.subList(Math.min(entry, exit), Math.max(entry, exit) + 1));
            if (entry > exit) {
                Collections.reverse(s);
            }
            out.add(s);
        }
        return out;
    }

    /** Photos every {@code step} m along the line from its first point, the first one at the start. */
    static List<Shot> along(List<TransectPoint> line, double step) {
        List<Shot> shots = new ArrayList<>();
        double next = 0;
        for (int i = 1; i < line.size(); i++) {
            GeoPoint a = line.get(i - 1).geo();
            GeoPoint b = line.get(i).geo();
            double length = QgcGeo.distance(a, b);
            double heading = QgcGeo.azimuth(a, b);
            for (; next <= length; next += step) {
                shots.add(new Shot(QgcGeo.destination(a, next, heading), heading));
            }
            next -= length;
        }
        return shots;
    }

    /** The photos of a transect survey: along each camera section, or at the hover stops. */
    static List<Shot> transectShots(List<List<TransectPoint>> transects, double triggerDistance, boolean hover) {
        List<Shot> shots = new ArrayList<>();
        if (triggerDistance <= 0) {
            return shots;
        }
        for (List<TransectPoint> s : sections(transects)) {
            if (hover) {
                GeoPoint start = s.get(0).geo();
                GeoPoint end = s.get(s.size() - 1).geo();
                double heading = QgcGeo.azimuth(start, end);
                s.forEach(p -> shots.add(new Shot(p.geo(), heading)));
            } else {
                shots.addAll(along(s, triggerDistance));
            }
        }
        return shots;
    }

    /** The ground each photo of a transect survey covers; none without a camera (its footprint is unknown). */
    static List<List<Position>> footprints(PhotoGrid grid, List<List<TransectPoint>> transects, boolean hover) {
        if (grid.manual()) {
            return List.of();
        }
        return transectShots(transects, grid.triggerDistance(), hover).stream()
                .map(s -> rectangle(s, grid.footprintSide(), grid.footprintFrontal()))
                .toList();
    }

    /** A ground rectangle {@code across} × {@code along} m centred on the shot, long side {@code along} on its heading. */
    private static List<Position> rectangle(Shot shot, double across, double along) {
        GeoPoint front = QgcGeo.destination(shot.centre(), along / 2, shot.heading());
        GeoPoint back = QgcGeo.destination(shot.centre(), -along / 2, shot.heading());
        double right = shot.heading() + 90;
        return List.of(QgcGeo.destination(front, -across / 2, right).position(),
                QgcGeo.destination(front, across / 2, right).position(),
                QgcGeo.destination(back, across / 2, right).position(),
                QgcGeo.destination(back, -across / 2, right).position());
    }
}
