package dolphin.sim;

/**
 * A firmware's flight numbers, the defaults of its parameters: metres per second and metres.
 *
 * @param speed horizontal speed in a mission (WPNAV_SPEED, cruise airspeed, WP_SPEED)
 * @param climb climb rate, also a take-off's
 * @param sink sink rate, also a landing's above LAND_ALT_LOW
 * @param waypointRadius how close a waypoint counts as reached (WPNAV_RADIUS, WP_RADIUS)
 * @param loiterRadius the circle of a loiter whose item gives none
 */
record Performance(double speed, double climb, double sink, double waypointRadius, double loiterRadius) {

    /** How close it flies to a point it must be over: a circle's entry, a landing point. */
    double precisionRadius() {
        return Math.min(waypointRadius, 5);
    }
}
