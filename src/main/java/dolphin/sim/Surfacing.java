package dolphin.sim;

import dolphin.core.Position;

/**
 * ArduSub's surfacing (NAV_LAND in a mission, SURFACE mode): to the point at the depth it had when
 * it started (Sub::do_surface), then straight up to the surface there, over once it is at the
 * surface (depth 0, not only within the waypoint radius of it). Without a point it goes straight
 * up where it is.
 */
final class Surfacing implements Manoeuvre {

    private final Firmware firmware;
    private final Craft craft;
    private final Position atDepth;
    private boolean ascending;

    /** Surfaces at {@code over} (lat, lon; its height does not matter), or where it is when null. */
    Surfacing(Firmware firmware, Craft craft, Position over) {
        this.firmware = firmware;
        this.craft = craft;
        this.atDepth = (over == null ? craft.position() : over).atHeight(craft.position().hae());
        this.ascending = over == null;
    }

    @Override
    public boolean step(double dt) {
        double radius = craft.performance().waypointRadius();
        if (!ascending) {
            ascending = firmware.reach(craft, atDepth, radius, 0, dt);
            return false;
        }
        boolean over = firmware.reach(craft, atDepth.atHeight(craft.ground()), radius, 0, dt);
        return over && craft.depth() <= 0;
    }
}
