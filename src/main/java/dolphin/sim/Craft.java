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
 * has landed or is disarmed where it touches.
 */
final class Craft {

    /** Heights above the ground up to this count as touching it. */
    static final double CONTACT = 0.01;

    private final double ground;
    private final Performance performance;
    private final Consumer<String> report;
    private Position position;
    private double speed;
    private double heading;
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

    /** Lands it if it touches the ground: a landing is complete, or it was disarmed there. */
    void settle() {
        if (contact) {
            onGround = true;
        }
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

    /**
     * Moves towards {@code t}: horizontally at its speed, vertically at the climb or sink rate. The
     * height to change is the difference of heights, not the local "down" towards {@code t}, which over
     * a kilometre includes the Earth's curvature (8 cm) and would bring a long leg at one height down
     * to the ground.
     */
    void fly(Position t, double dt) {
        double[] ned = position.displacementTo(t);
        double h = Math.hypot(ned[0], ned[1]);
        double f = h <= 0 ? 0 : Math.min(1, speed * dt / h);
        turnTowards(ned);
        double dz = Math.max(-performance.sink() * dt, Math.min(performance.climb() * dt, t.hae() - position.hae()));
        Position p = position.displace(ned[0] * f, ned[1] * f, 0);
        moveTo(p.atHeight(position.hae() + dz), dt);
    }

    /** Along the ground towards {@code t}, whose height does not matter, at its speed. */
    void drive(Position t, double dt) {
        double[] ned = position.displacementTo(t);
        double h = Math.hypot(ned[0], ned[1]);
        double f = h <= 0 ? 0 : Math.min(1, speed * dt / h);
        turnTowards(ned);
        Position p = position.displace(ned[0] * f, ned[1] * f, 0);
        position = p.atHeight(ground);
    }

    /** Straight up (or down) towards {@code hae} at the climb or sink rate. */
    void climbTo(double hae, double dt) {
        double up = hae - position.hae();
        moveTo(position.displace(0, 0, -Math.max(-performance.sink() * dt, Math.min(performance.climb() * dt, up))), dt);
    }

    /** Ahead along its heading at its speed, climbing towards {@code hae}: a plane's take-off run. */
    void climbAhead(double hae, double dt) {
        double d = speed * dt;
        double up = Math.min(performance.climb() * dt, hae - position.hae());
        moveTo(position.displace(d * Math.cos(heading), d * Math.sin(heading), -up), dt);
    }

    /** Straight down at {@code rate} m/s, to the ground at most. */
    void descend(double rate, double dt) {
        moveTo(position.displace(0, 0, rate * dt), dt);
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
        report.accept(String.format(Locale.ROOT, "SIM Hit ground at %f m/s", rate));
    }

    private void turnTowards(double[] ned) {
        if (Math.hypot(ned[0], ned[1]) > 0.01) {
            heading = Math.atan2(ned[1], ned[0]);
        }
    }
}
