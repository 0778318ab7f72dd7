package dolphin.sim;

import com.MAVLink.enums.MAV_LANDED_STATE;
import dolphin.core.Position;
import java.util.Locale;

/**
 * A QuadPlane's vertical landing (NAV_VTOL_LAND, NAV_LAND, QRTL, QLAND), in the stages and with the
 * texts of QuadPlane::vtol_position_controller, simplified: APPROACH flies to the point as a plane at
 * its height, from more than 1.5 stopping distances at cruise speed away; AIRBRAKE, once within the
 * stopping distance (v²/(2 Q_TRANS_DECEL), plus two seconds at its speed), slows at Q_TRANS_DECEL for
 * a second; POSITION1 closes at the speed from which it stops {@link #POSITION2_DISTANCE} metres short
 * at {@link #POSITION2_SPEED}; POSITION2 stops over the point; LAND_DESCEND descends at Q_WP_SPEED_DN,
 * slowing to Q_LAND_FINAL_SPD between Q_LAND_FINAL_ALT + 6 and Q_LAND_FINAL_ALT; LAND_FINAL goes on
 * at Q_LAND_FINAL_SPD to the ground, and the landing is complete {@link #DETECT} seconds after the touch.
 * Not simulated: the approach's descent and loiter, the Q_RTL_ALT climb, overshoots and aborts.
 */
final class VtolLanding implements Manoeuvre {

    /** Q_TRANS_DECEL, m/s². */
    static final double TRANS_DECEL = 2;
    static final double POSITION2_DISTANCE = 10;
    static final double POSITION2_SPEED = 3;
    /** Q_WP_SPEED_DN. */
    static final double DESCENT = 1.5;
    /** Q_LAND_FINAL_ALT. */
    static final double FINAL_ALT = 6;
    /** Q_LAND_FINAL_SPD. */
    static final double FINAL_SPEED = 0.5;
    /** At least this long in AIRBRAKE (QuadPlane: "use at least 1s of airbrake time"). */
    static final double AIRBRAKE_SECONDS = 1;
    /** From the touch to "Land complete": SITL took 6 s (land_detector's 4 s, and the lower limit's). */
    static final double DETECT = 6;

    private enum PositionState { APPROACH, AIRBRAKE, POSITION1, POSITION2, DESCEND, FINAL }

    private final QuadPlaneFirmware firmware;
    private final VtolLift lift;
    private final Craft craft;
    private final Position over;
    private PositionState stage;
    private double speed;
    private double timer;

    /** Lands at {@code over} (its height does not matter); null: where it is, straight down (QLAND). */
    VtolLanding(QuadPlaneFirmware firmware, VtolLift lift, Craft craft, Position over) {
        this.firmware = firmware;
        this.lift = lift;
        this.craft = craft;
        this.over = over != null ? over : craft.position();
        this.speed = craft.speed();
        if (over == null) {
            lift.hover();
            stage = PositionState.DESCEND;
            return;
        }
        double d = craft.distanceTo(over);
        if (d >= 1.5 * stoppingDistance(craft.performance().speed())) {
            craft.say(String.format(Locale.ROOT, "VTOL approach d=%.1f", d));
            stage = PositionState.APPROACH;
        } else if (lift.hovering()) {
            craft.say(String.format(Locale.ROOT, "VTOL Position1 d=%.1f", d));
            speed = Math.max(closingSpeed(d), POSITION2_SPEED);
            stage = PositionState.POSITION1;
        } else {
            airbrake(d);
        }
    }

    /** v²/(2 Q_TRANS_DECEL) (QuadPlane::stopping_distance_m). */
    static double stoppingDistance(double speed) {
        return speed * speed / (2 * TRANS_DECEL);
    }

    @Override
    public boolean step(double dt) {
        Position target = over.atHeight(craft.position().hae());
        double d = craft.distanceTo(target);
        switch (stage) {
            case APPROACH -> {
                firmware.reach(craft, target, 0, craft.speed(), dt);
                speed = Math.min(craft.speed(), lift.airspeed());
                if (craft.distanceTo(target) < stoppingDistance(speed) + 2 * speed) {
                    airbrake(craft.distanceTo(target));
                }
            }
            case AIRBRAKE -> {
                speed = Math.max(POSITION2_SPEED, speed - TRANS_DECEL * dt);
                craft.fly(target, 0, 0, speed, dt);
                timer += dt;
                if (timer >= AIRBRAKE_SECONDS) {
                    craft.say(String.format(Locale.ROOT, "VTOL position1 v=%.1f d=%.1f h=%.1f dc=%.1f", speed, d, craft.height(),
                            closingSpeed(d)));
                    stage = PositionState.POSITION1;
                }
            }
            case POSITION1 -> {
                brake(target, dt);
                d = craft.distanceTo(target);
                if (d < POSITION2_DISTANCE && speed < 3 * POSITION2_SPEED) {
                    craft.say(String.format(Locale.ROOT, "VTOL position2 started v=%.1f d=%.1f h=%.1f", speed, d, craft.height()));
                    lift.hover();
                    stage = PositionState.POSITION2;
                }
            }
            case POSITION2 -> {
                craft.fly(target, 0, 0, POSITION2_SPEED, dt);
                if (craft.distanceTo(target) < 0.01) {
                    craft.say("Land descend started");
                    stage = PositionState.DESCEND;
                }
            }
            case DESCEND -> {
                double h = craft.height();
                craft.descend(FINAL_SPEED + (DESCENT - FINAL_SPEED) * Math.max(0, Math.min(1, (h - FINAL_ALT) / 6)), dt);
                if (craft.height() < FINAL_ALT) {
                    craft.say("Land final started");
                    stage = PositionState.FINAL;
                }
            }
            case FINAL -> {
                if (!craft.contact()) {
                    craft.descend(FINAL_SPEED, dt);
                    return false;
                }
                timer += dt;
                if (timer >= DETECT) {
                    craft.say("Land complete");
                    return true;
                }
            }
        }
        return false;
    }

    private void airbrake(double d) {
        craft.say(String.format(Locale.ROOT, "VTOL airbrake v=%.1f d=%.0f sd=%.0f h=%.1f", speed, d,
                stoppingDistance(speed) + 2 * speed, craft.height()));
        lift.airbrake();
        timer = 0;
        stage = PositionState.AIRBRAKE;
    }

    /** Towards the point, slowing at Q_TRANS_DECEL while faster than the closing speed. */
    private void brake(Position target, double dt) {
        double want = Math.max(closingSpeed(craft.distanceTo(target)), POSITION2_SPEED);
        speed = speed > want ? Math.max(want, speed - TRANS_DECEL * dt) : speed;
        craft.fly(target, 0, 0, speed, dt);
    }

    /** The speed from which it stops POSITION2_DISTANCE short of the point at POSITION2_SPEED. */
    private static double closingSpeed(double d) {
        return Math.sqrt(Math.max(0, d - POSITION2_DISTANCE) * 2 * TRANS_DECEL + POSITION2_SPEED * POSITION2_SPEED);
    }

    /** LANDING from the descent on (GCS_MAVLINK_Plane::landed_state: is_landing()), IN_AIR before. */
    @Override
    public int landedState() {
        return stage == PositionState.DESCEND || stage == PositionState.FINAL ? MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING
                : MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR;
    }

    @Override
    public boolean endsOnGround() {
        return true;
    }
}
