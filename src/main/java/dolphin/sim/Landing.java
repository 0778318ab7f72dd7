package dolphin.sim;

import com.MAVLink.enums.MAV_LANDED_STATE;
import dolphin.core.Position;

/**
 * ArduCopter's landing (NAV_LAND, LAND mode, the end of RTL; a plane's is simplified to the same):
 * over the landing point at its height, stopped, then straight down at the sink rate above
 * LAND_ALT_LOW and LAND_SPEED below it, to the ground. It is over when the land detector has seen
 * the craft on the ground for {@link #DETECT} seconds (SITL disarms about 2 s after it touches down).
 */
class Landing implements Manoeuvre {

    static final double LAND_SPEED = 0.5;
    static final double LAND_ALT_LOW = 10;
    static final double DETECT = 2;

    private final Craft craft;
    private final Position over;
    private boolean above;
    private double grounded;

    /** Lands at {@code over} (lat, lon; its height does not matter), or where it is when null. */
    Landing(Craft craft, Position over) {
        this.craft = craft;
        this.over = over;
        this.above = over == null;
    }

    @Override
    public boolean step(double dt) {
        if (!above) {
            Position target = over.atHeight(craft.position().hae());
            craft.fly(target, dt);
            above = craft.distanceTo(target) <= craft.performance().precisionRadius() && craft.stopped();
            return false;
        }
        if (!craft.contact()) {
            craft.descend(sinkRate(craft), dt);
            return false;
        }
        grounded += dt;
        return grounded >= detectSeconds();
    }

    /** How fast it comes down, metres a second, at the craft's height. */
    double sinkRate(Craft craft) {
        return craft.height() > LAND_ALT_LOW ? craft.performance().sink() : LAND_SPEED;
    }

    /** How long its land detector must see the ground. */
    double detectSeconds() {
        return DETECT;
    }

    /** Whether it is over the landing point, coming down. */
    final boolean descending() {
        return above;
    }

    @Override
    public int landedState() {
        return MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING;
    }

    @Override
    public boolean endsOnGround() {
        return true;
    }
}
