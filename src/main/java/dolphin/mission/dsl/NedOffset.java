package dolphin.mission.dsl;

import dolphin.core.Position;

/**
 * A (north, east, down) offset in metres, as {@code moveDistance { north n; east e; down d }} makes it.
 */
public record NedOffset(double north, double east, double down) {

    /** The position this offset away from {@code from}: see {@link #offset}. */
    public Position from(Position from) {
        return offset(from, north, east, down);
    }

    /**
     * {@code from} moved by (north, east, down) metres. Latitude and longitude come from the
     * original's WGS-84 displacement by (north, east, 0) (tangent plane at {@code from}, with its
     * geocentric-latitude quirk); the height is exactly {@code from}'s height minus
     * {@code down}. The original displaced by (north, east, down) in one step: its tilted "down" put a
     * 100 m climb about 0.33 m north, and the tangent plane and the tilt left the height off by up to
     * 0.3 m per 100 m north at these latitudes; here "100 m up" is straight up, to the metre.
     */
    public static Position offset(Position from, double north, double east, double down) {
        Position p = from.displace(north, east, 0);
        return p.atHeight(from.hae() - down);
    }
}
