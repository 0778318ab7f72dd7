package dolphin.mission.model;

import dolphin.core.Position;
import java.util.List;

/**
 * One region of a geofence, as ArduPilot's AC_PolyFence keeps them: a polygon or a circle that the
 * vehicle must stay inside (inclusion) or outside (exclusion). Heights play no part: ArduPilot's
 * polygon and circle fences are horizontal, the maximum altitude is the FENCE_ALT_MAX parameter.
 */
public sealed interface FenceRegion permits FenceRegion.Polygon, FenceRegion.Circle {

    /** True when the vehicle must stay inside, false when it must stay outside. */
    boolean inclusion();

    /** Whether a position is inside the region (its height ignored). */
    boolean contains(Position p);

    /** "inclusion polygon of 4 vertices" and the like, for messages and tables. */
    String describe();

    /** A polygon of at least 3 vertices, not closed (the last vertex is not the first repeated). */
    record Polygon(boolean inclusion, List<Position> vertices) implements FenceRegion {

        public Polygon {
            vertices = List.copyOf(vertices);
            if (vertices.size() < 3) {
                throw new IllegalArgumentException("a fence polygon needs at least 3 vertices, found " + vertices.size());
            }
        }

        /**
         * Even-odd ray casting on a local flat projection around the point (metres east and north),
         * as AC_PolyFence does on its NE offsets: exact enough for fences of a few kilometres.
         */
        @Override
        public boolean contains(Position p) {
            boolean inside = false;
            int n = vertices.size();
            double[] prev = local(p, vertices.get(n - 1));
            for (Position v : vertices) {
                double[] cur = local(p, v);
                if ((cur[1] > 0) != (prev[1] > 0)) {
                    double eastAtAxis = cur[0] + (0 - cur[1]) * (prev[0] - cur[0]) / (prev[1] - cur[1]);
                    if (eastAtAxis > 0) {
                        inside = !inside;
                    }
                }
                prev = cur;
            }
            return inside;
        }

        @Override
        public String describe() {
            return (inclusion ? "inclusion" : "exclusion") + " polygon of " + vertices.size() + " vertices";
        }

        /** {east, north} metres from {@code origin} to {@code v} on the tangent plane. */
        private static double[] local(Position origin, Position v) {
            double north = (v.lat() - origin.lat()) * dolphin.core.Wgs84.A;
            double east = (v.lon() - origin.lon()) * dolphin.core.Wgs84.A * Math.cos(origin.lat());
            return new double[] {east, north};
        }
    }

    /** A circle of {@code radius} metres around {@code center}. */
    record Circle(boolean inclusion, Position center, double radius) implements FenceRegion {

        public Circle {
            if (!(radius > 0) || Double.isInfinite(radius)) {
                throw new IllegalArgumentException("a fence circle needs a radius above 0 m, found " + radius);
            }
        }

        @Override
        public boolean contains(Position p) {
            return center.horizontalDistanceTo(p) <= radius;
        }

        @Override
        public String describe() {
            return (inclusion ? "inclusion" : "exclusion") + " circle of " + ItemText.number((float) radius) + " m";
        }
    }
}
