package dolphin.sim;

/**
 * A firmware's flight numbers, the values of its parameters under SITL: metres per second, metres
 * and metres per second squared.
 *
 * @param speed horizontal speed in a mission (WPNAV_SPD, cruise airspeed, WP_SPEED)
 * @param climb climb rate, also a take-off's
 * @param sink sink rate, also a landing's above LAND_ALT_LOW
 * @param waypointRadius how close a waypoint counts as reached (WPNAV_RADIUS_M, WP_RADIUS)
 * @param loiterRadius the circle of a loiter whose item gives none
 * @param accel horizontal acceleration and braking (WPNAV_ACC, ATC_ACCEL_MAX); 0: at its speed at once
 * @param cornerSpeed the speed at which it comes within the radius of a waypoint where its track turns
 *        through a right angle (its navigation slows down for the turn; SITL's copter and rover both come
 *        in at about 2.5 m/s)
 */
record Performance(double speed, double climb, double sink, double waypointRadius, double loiterRadius, double accel,
                   double cornerSpeed) {

    /** How close it flies to a point it must be over: a circle's entry, a landing point. */
    double precisionRadius() {
        return Math.min(waypointRadius, 5);
    }

    /**
     * The speed at which it passes a waypoint where its track turns by {@code turn} radians: its
     * full speed straight on, slowing with the turn down to {@link #cornerSpeed} at a right angle and beyond.
     */
    double passingSpeed(double speedNow, double turn) {
        return Math.max(Math.min(cornerSpeed, speedNow), speedNow * Math.cos(Math.min(Math.abs(turn), Math.PI / 2)));
    }
}
