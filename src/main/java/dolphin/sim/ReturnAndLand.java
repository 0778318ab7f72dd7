package dolphin.sim;

import dolphin.core.Position;

/**
 * ArduCopter's RTL (ModeRTL): at its own speed (RTL_SPEED_MS 0 is WPNAV_SPD, whatever DO_CHANGE_SPEED
 * set), up to RTL_ALT_M above home if lower, home at that height, {@link #LOITER_TIME} seconds over
 * it (RTL_LOIT_TIME), then a {@link Landing} there; only that final descent counts as landing
 * (docs/mavlink.md, "The simulated fleet and real ArduPilot").
 */
final class ReturnAndLand implements Manoeuvre {

    static final double RTL_ALT = 15;
    static final double LOITER_TIME = 5;

    private final Craft craft;
    private final Position home;
    private final double returnAltitude;
    private final double loiterTime;
    private boolean climbed;
    private boolean over;
    private double loitered;
    private Landing landing;

    ReturnAndLand(Craft craft, Position home) {
        this(craft, home, RTL_ALT, LOITER_TIME);
    }

    /** Up to {@code returnAltitude} above home, and {@code loiterTime} seconds over it before the landing. */
    ReturnAndLand(Craft craft, Position home, double returnAltitude, double loiterTime) {
        this.craft = craft;
        this.home = home;
        this.returnAltitude = returnAltitude;
        this.loiterTime = loiterTime;
        craft.resetSpeed();
    }

    @Override
    public boolean step(double dt) {
        if (!climbed) {
            double alt = home.hae() + returnAltitude;
            craft.climbTo(Math.max(alt, craft.position().hae()), dt);
            climbed = craft.position().hae() >= alt - 0.05 && craft.stopped();
            return false;
        }
        if (!over) {
            Position above = home.atHeight(craft.position().hae());
            craft.fly(above, dt);
            over = craft.distanceTo(above) <= craft.performance().waypointRadius() && craft.stopped();
            return false;
        }
        if (loitered < loiterTime) {
            loitered += dt;
            return false;
        }
        if (landing == null) {
            landing = new Landing(craft, null);
        }
        return landing.step(dt);
    }

    @Override
    public int landedState() {
        return landing == null ? Manoeuvre.super.landedState() : landing.landedState();
    }

    @Override
    public boolean endsOnGround() {
        return true;
    }
}
