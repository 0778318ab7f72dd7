package dolphin.sim;

import dolphin.core.Position;

/**
 * Circles a point at its radius, at the craft's speed or, for a craft with an acceleration limit,
 * no faster than that acceleration holds it on the circle (v² = a r), for a number of turns
 * (infinite: for ever), from the point of the circle nearest the craft (its north point when the
 * craft is at the centre): the craft follows a point going round, moving as its firmware moves it.
 */
final class Orbit implements Manoeuvre {

    private final Firmware firmware;
    private final Craft craft;
    private final Position centre;
    private final double radius;
    private final double turns;
    private final double start;
    private double angle;

    Orbit(Firmware firmware, Craft craft, Position centre, double radius, double turns) {
        this.firmware = firmware;
        this.craft = craft;
        this.centre = centre;
        this.radius = radius;
        this.turns = turns;
        double[] ned = centre.displacementTo(craft.position());
        this.start = Math.hypot(ned[0], ned[1]) > 0.01 ? Math.atan2(ned[1], ned[0]) : 0;
    }

    /** Where the circle starts. */
    static Position entry(Position centre, double radius) {
        return centre.displace(radius, 0, 0);
    }

    @Override
    public boolean step(double dt) {
        double accel = craft.performance().accel();
        double speed = accel > 0 ? Math.min(craft.speed(), Math.sqrt(accel * radius)) : craft.speed();
        angle += speed / radius * dt;
        double done = 2 * Math.PI * Math.max(0, turns);
        double a = start + Math.min(angle, done);
        firmware.reach(craft, centre.displace(radius * Math.cos(a), radius * Math.sin(a), 0), 0, speed, dt);
        return angle >= done;
    }
}
