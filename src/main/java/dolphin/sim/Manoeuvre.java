package dolphin.sim;

import com.MAVLink.enums.MAV_LANDED_STATE;

/**
 * One stretch of a simulated vehicle's movement with a beginning and, usually, an end: a take-off,
 * a landing, a return home, a loiter. Made by a {@link Firmware}, stepped by {@link MissionFlight}.
 */
@FunctionalInterface
interface Manoeuvre {

    /** Ends at once: what a vehicle cannot do, e.g. a rover's take-off. */
    Manoeuvre DONE = dt -> true;

    /** Moves the vehicle on by {@code dt} seconds; true once the manoeuvre is over. */
    boolean step(double dt);

    /** MAV_LANDED_STATE while it runs and the vehicle is off the ground: TAKEOFF, LANDING or IN_AIR. */
    default int landedState() {
        return MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR;
    }

    /** Whether it ends with the vehicle landed, to be disarmed. */
    default boolean endsOnGround() {
        return false;
    }
}
