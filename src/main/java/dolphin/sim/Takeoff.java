package dolphin.sim;

import com.MAVLink.enums.MAV_LANDED_STATE;

/**
 * NAV_TAKEOFF: after the firmware's wait on the ground, climbs to the item's height the firmware's
 * way, a copter straight up at its climb rate ({@link Craft#climbTo}), a plane ahead along its heading
 * at its speed ({@link Craft#climbAhead}).
 */
final class Takeoff implements Manoeuvre {

    /** One step of the climb towards an altitude. */
    interface Climb {
        void step(double altitude, double dt);
    }

    private static final double TOLERANCE = 0.05;

    private final Craft craft;
    private final double altitude;
    private final Climb climb;
    private double wait;

    /** A take-off that stays on the ground for {@code waitSeconds} first (a copter's motors spooling up). */
    Takeoff(Craft craft, double altitude, Climb climb, double waitSeconds) {
        this.craft = craft;
        this.altitude = altitude;
        this.climb = climb;
        this.wait = waitSeconds;
    }

    @Override
    public boolean step(double dt) {
        if (wait > 0) {
            wait -= dt;
            return false;
        }
        if (altitude - craft.position().hae() > TOLERANCE) {
            climb.step(altitude, dt);
        }
        return altitude - craft.position().hae() <= TOLERANCE;
    }

    @Override
    public int landedState() {
        return MAV_LANDED_STATE.MAV_LANDED_STATE_TAKEOFF;
    }
}
