package dolphin.sim;

import com.MAVLink.enums.MAV_LANDED_STATE;

/** A plane's NAV_TAKEOFF: ahead along its heading at its speed, climbing to the item's height. */
final class RollingTakeoff implements Manoeuvre {

    private static final double TOLERANCE = 0.05;

    private final Craft craft;
    private final double altitude;

    RollingTakeoff(Craft craft, double altitude) {
        this.craft = craft;
        this.altitude = altitude;
    }

    @Override
    public boolean step(double dt) {
        if (altitude - craft.position().hae() > TOLERANCE) {
            craft.climbAhead(altitude, dt);
        }
        return altitude - craft.position().hae() <= TOLERANCE;
    }

    @Override
    public int landedState() {
        return MAV_LANDED_STATE.MAV_LANDED_STATE_TAKEOFF;
    }
}
