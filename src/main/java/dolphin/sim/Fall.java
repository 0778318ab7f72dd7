package dolphin.sim;

/**
 * A vehicle coming down without thrust: straight down, faster by {@link FaultTable#FALL_ACCEL} each
 * second up to {@link FaultTable#FALL_SPEED}, its horizontal speed braked away, until it touches the
 * ground, where its craft reports the speed it hit at ("SIM Hit ground at ... m/s").
 */
final class Fall {

    private double speed;

    /** One step of {@code dt} seconds, for a craft not yet on the ground. */
    void step(Craft craft, double dt) {
        speed = Math.min(FaultTable.FALL_SPEED, speed + FaultTable.FALL_ACCEL * dt);
        craft.descend(speed, dt);
    }
}
