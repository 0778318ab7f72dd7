package dolphin.sim;

import dolphin.core.Position;

/**
 * ArduCopter's RTL: up to RTL_ALT above home if lower, home at that height, then a {@link Landing}
 * there (only its final descent counts as landing).
 */
final class ReturnAndLand implements Manoeuvre {

    static final double RTL_ALT = 15;

    private final Craft craft;
    private final Position home;
    private boolean climbed;
    private Landing landing;

    ReturnAndLand(Craft craft, Position home) {
        this.craft = craft;
        this.home = home;
    }

    @Override
    public boolean step(double dt) {
        if (!climbed) {
            double alt = home.hae() + RTL_ALT;
            craft.climbTo(Math.max(alt, craft.position().hae()), dt);
            climbed = craft.position().hae() >= alt - 0.05;
            return false;
        }
        if (landing == null) {
            Position over = home.atHeight(craft.position().hae());
            craft.fly(over, dt);
            if (craft.distanceTo(over) <= craft.performance().waypointRadius()) {
                landing = new Landing(craft, null);
            }
            return false;
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
