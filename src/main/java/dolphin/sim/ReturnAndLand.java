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
    private boolean climbed;
    private boolean over;
    private double loitered;
    private Landing landing;

    ReturnAndLand(Craft craft, Position home) {
        this.craft = craft;
        this.home = home;
        craft.resetSpeed();
    }

    @Override
    public boolean step(double dt) {
        if (!climbed) {
            double alt = home.hae() + RTL_ALT;
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
        if (loitered < LOITER_TIME) {
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
