package dolphin.sim;

import dolphin.core.Position;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * The body of a simulated vehicle over flat ground at the height of the home it was created with
 * (SITL's --home): where it is, how fast it goes, and the moves the firmwares make of it. It never
 * goes below the ground: a move that would ends on it, there it stops (as SITL's vehicles stick
 * where they touch), and each new touch is reported as SITL reports it ("SIM Hit ground at 0.5
 * m/s"). It is on the ground (MAV_LANDED_STATE_ON_GROUND) until it lifts off, and again once it
 * has landed or is disarmed where it touches. Over the ground it moves with a velocity that changes
 * at most at its firmware's acceleration (none given: it is at its speed at once, as a plane here),
 * so it gathers speed, brakes for a point it stops at and overshoots one it turns back from.
 * A submarine's craft moves under the surface instead ({@link #dive}): the home's height is then
 * the water's surface, which it never rises above, and it has no ground to touch.
 */
final class Craft {

    /** Heights above the ground up to this count as touching it. */
    static final double CONTACT = 0.01;
    /** Slower than this over the ground counts as stopped. */
    static final double STOPPED = 0.05;

    private final double ground;
    private final Performance performance;
    private final Consumer<String> report;
    private Position position;
    private double speed;
    private double heading;
    // horizontal velocity, m/s north and east
    private double north;
    private double east;
    private boolean contact = true;
    private boolean onGround = true;

    /** A craft resting at {@code start}, whose height is the ground's; touches are told to {@code report}. */
    Craft(Position start, Performance performance, Consumer<String> report) {
        this.position = start;
        this.ground = start.hae();
        this.performance = performance;
        this.report = report;
        this.speed = performance.speed();
    }

    Position position() {
        return position;
    }

    Performance performance() {
        return performance;
    }

    /** The ground's height above the ellipsoid. */
    double ground() {
        return ground;
    }

    /** Height above the ground. */
    double height() {
        return position.hae() - ground;
    }

    /** Touching the ground, landed or not. */
    boolean contact() {
        return contact;
    }

    /** Landed, or never lifted off: not flying. */
    boolean onGround() {
        return onGround;
    }

    /** Says {@code text} as the vehicle (INFO), as it reports its touches. */
    void say(String text) {
        report.accept(text);
    }

    /** Lands it if it touches the ground: a landing is complete, or it was disarmed there. */
    void settle() {
        if (contact) {
            onGround = true;
            stop();
        }
    }

    /** Not moving over the ground (always, for a craft without an acceleration limit). */
    boolean stopped() {
        return Math.hypot(north, east) < STOPPED;
    }

    double speed() {
        return speed;
    }

    /** DO_CHANGE_SPEED: m/s from now on. */
    void speed(double metresPerSecond) {
        speed = metresPerSecond;
    }

    /** Back to the firmware's own speed, as a new AUTO run starts with. */
    void resetSpeed() {
        speed = performance.speed();
    }

    /** The direction it last moved in, radians from north. */
    double heading() {
        return heading;
    }

    /** The horizontal distance to {@code p}. */
    double distanceTo(Position p) {
        return position.horizontalDistanceTo(p);
    }

    /** Towards {@code t} to stop over it; see {@link #fly(Position, double, double, double)}. */
    void fly(Position t, double dt) {
        fly(t, 0, 0, dt);
    }

    /**
     * Moves towards {@code t}, horizontally to come within {@code within} metres of it at
     * {@code endSpeed} (0: to stop on it), vertically at the climb or sink rate. The height to change
     * is the difference of heights, not the local "down" towards {@code t}, which over a kilometre
     * includes the Earth's curvature (8 cm) and would bring a long leg at one height down to the ground.
     */
    void fly(Position t, double endSpeed, double within, double dt) {
        fly(t, endSpeed, within, speed, dt);
    }

    /** As {@link #fly(Position, double, double, double)}, no faster than {@code speedLimit} m/s: a QuadPlane transitioning or braking. */
    void fly(Position t, double endSpeed, double within, double speedLimit, double dt) {
        double[] ned = position.displacementTo(t);
        double[] step = horizontal(ned[0], ned[1], endSpeed, endSpeed > 0 ? within : 0, false, Math.min(speed, speedLimit), dt);
        double dz = Math.max(-performance.sink() * dt, Math.min(performance.climb() * dt, t.hae() - position.hae()));
        Position p = position.displace(step[0], step[1], 0);
        moveTo(p.atHeight(position.hae() + dz), dt);
    }

    /**
     * Under water towards {@code t}: horizontally as {@link #fly(Position, double, double, double)},
     * vertically at the climb or sink rate, and never above the surface (the home's height), however
     * high {@code t} lies.
     */
    void dive(Position t, double endSpeed, double within, double dt) {
        double[] ned = position.displacementTo(t);
        double[] step = horizontal(ned[0], ned[1], endSpeed, endSpeed > 0 ? within : 0, false, speed, dt);
        double gap = t.hae() - position.hae();
        // the last step ends on the target's height itself, so a sub sent to the surface is at depth 0, not a rounding below it
        double hae = gap > performance.climb() * dt ? position.hae() + performance.climb() * dt
                : gap < -performance.sink() * dt ? position.hae() - performance.sink() * dt : t.hae();
        position = position.displace(step[0], step[1], 0).atHeight(Math.min(ground, hae));
    }

    /** How far below the surface (the home's height) it is; 0 at or above it. */
    double depth() {
        return Math.max(0, ground - position.hae());
    }

    /** Along the ground to stop at {@code t}, whose height does not matter. */
    void drive(Position t, double dt) {
        drive(t, 0, 0, dt);
    }

    /**
     * Along the ground towards {@code t}, whose height does not matter, to come within {@code within}
     * metres of it at {@code endSpeed}: steered, it heads for the point at once and only its speed is
     * held to its acceleration.
     */
    void drive(Position t, double endSpeed, double within, double dt) {
        double[] ned = position.displacementTo(t);
        double[] step = horizontal(ned[0], ned[1], endSpeed, endSpeed > 0 ? within : 0, true, speed, dt);
        position = position.displace(step[0], step[1], 0).atHeight(ground);
    }

    /** Straight up (or down) towards {@code hae} at the climb or sink rate, braking to a stop over the ground. */
    void climbTo(double hae, double dt) {
        climbTo(hae, performance.climb(), performance.sink(), dt);
    }

    /** Straight up at {@code climb} m/s (or down at {@code sink}) towards {@code hae}, braking to a stop over the ground. */
    void climbTo(double hae, double climb, double sink, double dt) {
        double up = Math.max(-sink * dt, Math.min(climb * dt, hae - position.hae()));
        double[] step = brake(dt);
        moveTo(position.displace(step[0], step[1], 0).atHeight(position.hae() + up), dt);
    }

    /** Ahead along its heading at its speed, climbing towards {@code hae}: a plane's take-off run. */
    void climbAhead(double hae, double dt) {
        ahead(-Math.min(performance.climb() * dt, hae - position.hae()), dt);
    }

    /** Ahead along its heading at its speed, sinking at {@code sink} m/s: a plane without its engine. */
    void glide(double sink, double dt) {
        ahead(sink * dt, dt);
    }

    /**
     * One step of {@code dt} seconds along its heading at its speed, {@code down} metres lower: lower
     * than its height, not along the local vertical, which over a long glide includes the Earth's curvature.
     */
    private void ahead(double down, double dt) {
        double d = speed * dt;
        moveTo(position.displace(d * Math.cos(heading), d * Math.sin(heading), 0).atHeight(position.hae() - down), dt);
    }

    /** Straight down at {@code rate} m/s, to the ground at most, braking to a stop over the ground. */
    void descend(double rate, double dt) {
        double[] step = brake(dt);
        moveTo(position.displace(step[0], step[1], 0).atHeight(position.hae() - rate * dt), dt);
    }

    /**
     * Moves to {@code p} in {@code dt} seconds. A move that would end at or below the ground ends on
     * it, reported with its vertical speed; a craft already touching stays where it is unless the
     * move lifts it.
     */
    void moveTo(Position p, double dt) {
        if (p.hae() - ground > CONTACT) {
            position = p;
            contact = false;
            onGround = false;
            return;
        }
        if (contact) {
            return;
        }
        double rate = dt > 0 ? (position.hae() - p.hae()) / dt : 0;
        position = p.atHeight(ground);
        contact = true;
        stop();
        report.accept(String.format(Locale.ROOT, "SIM Hit ground at %f m/s", rate));
    }

    /**
     * One step of a horizontal move towards a point {@code n}, {@code e} metres away. Without an
     * acceleration limit it goes at its speed at once. Otherwise it aims for the velocity that takes it
     * there no faster than it can brake to {@code endSpeed} by {@code within} metres of the point
     * (v² = end² + 2 a (d - within)), as ArduPilot's waypoint navigation does: a craft that flies
     * changes its velocity by at most accel * dt (so it overshoots a point it turns back from), a
     * {@code steered} one heads for the point and changes its speed only by that much. The step onto a
     * point where it stops ends on it, stopped.
     */
    private double[] horizontal(double n, double e, double endSpeed, double within, boolean steered, double speed, double dt) {
        double d = Math.hypot(n, e);
        double accel = performance.accel();
        if (accel <= 0) {
            double f = d <= 0 ? 0 : Math.min(1, speed * dt / d);
            turnTowards(n, e);
            return new double[] {n * f, e * f};
        }
        double want = d <= 0 ? 0 : Math.min(speed, Math.sqrt(endSpeed * endSpeed + 2 * accel * Math.max(0, d - within)));
        if (steered) {
            double now = Math.hypot(north, east);
            double v = Math.max(now - accel * dt, Math.min(now + accel * dt, want));
            north = d <= 0 ? 0 : n / d * v;
            east = d <= 0 ? 0 : e / d * v;
        } else {
            double dn = (d <= 0 ? 0 : n / d * want) - north;
            double de = (d <= 0 ? 0 : e / d * want) - east;
            double change = Math.hypot(dn, de);
            if (change > accel * dt) {
                dn *= accel * dt / change;
                de *= accel * dt / change;
            }
            north += dn;
            east += de;
        }
        if (endSpeed <= 0 && Math.hypot(north, east) * dt >= d) {
            stop();
            return new double[] {n, e};
        }
        turnTowards(north, east);
        return new double[] {north * dt, east * dt};
    }

    /** One step of slowing to a stop at its acceleration limit, for a move that is not over the ground. */
    private double[] brake(double dt) {
        double v = Math.hypot(north, east);
        if (v <= 0) {
            return new double[] {0, 0};
        }
        double f = Math.max(0, v - performance.accel() * dt) / v;
        north *= f;
        east *= f;
        return new double[] {north * dt, east * dt};
    }

    private void stop() {
        north = 0;
        east = 0;
    }

    private void turnTowards(double n, double e) {
        if (Math.hypot(n, e) > 0.01) {
            heading = Math.atan2(e, n);
        }
    }
}
