package dolphin.mission.model;

import java.util.Locale;

/**
 * What makes a mission an underwater one (docs/underwater.md): the height of the water's surface
 * (metres above mean sea level: the mission's home, or sea level when it names none) and how deep
 * below it the script lets the mission go ({@code maxDepth}). A submarine flies only such missions,
 * and no other vehicle does; their items must stay between the surface and that depth.
 */
public record Underwater(double surface, double maxDepth) {

    public Underwater {
        if (!Double.isFinite(surface)) {
            throw new IllegalArgumentException("the surface's height must be a number of metres, got " + surface);
        }
        if (!(maxDepth > 0) || Double.isInfinite(maxDepth)) {
            throw new IllegalArgumentException("maxDepth: the depth limit must be a positive number of metres, got " + maxDepth);
        }
    }

    /** The depth of a height above mean sea level: metres below the surface, negative above it. */
    public double depthOf(double hae) {
        return surface - hae;
    }

    /** The height above mean sea level {@code depth} metres below the surface. */
    public double heightAt(double depth) {
        return surface - depth;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "under water, surface at %.1f m, at most %.1f m deep", surface, maxDepth);
    }
}
