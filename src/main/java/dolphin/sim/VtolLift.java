package dolphin.sim;

import com.MAVLink.enums.MAV_VTOL_STATE;
import java.util.Locale;

/**
 * What holds a QuadPlane up, as ArduPlane's SLT_Transition keeps it: its lift motors (hovering), its
 * wing, or both while it changes over. Flying forward from a hover it transitions (AIRSPEED_WAIT, then
 * TIMER): it gathers speed at {@link #TRANSITION_ACCEL}, is told "Transition airspeed reached" at
 * Q_ASSIST_SPEED and "Transition done" Q_TRANSITION_MS later. Its MAV_VTOL_STATE is
 * SLT_Transition::get_mav_vtol_state's. It starts on its wing, as a plane in MANUAL does.
 */
final class VtolLift {

    /** Q_ASSIST_SPEED in quadplane.parm: below it the lift motors help; above it the transition's timer runs. */
    static final double ASSIST_SPEED = 18;
    /** Q_TRANSITION_MS: seconds from the airspeed reached to the transition done. */
    static final double TRANSITION_SECONDS = 5;
    /** How fast SITL's quadplane gathered speed in its transition: 0.7 to 18.1 m/s in 4.5 s. */
    static final double TRANSITION_ACCEL = 4;

    private enum TransitionState {
        HOVER(MAV_VTOL_STATE.MAV_VTOL_STATE_MC),
        AIRSPEED_WAIT(MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_FW),
        TIMER(MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_FW),
        WING(MAV_VTOL_STATE.MAV_VTOL_STATE_FW),
        AIRBRAKE(MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_MC);

        private final int mavState;

        TransitionState(int mavState) {
            this.mavState = mavState;
        }
    }

    private TransitionState stage = TransitionState.WING;
    private double airspeed;
    private double timer;

    /** On its lift motors: taking off, hovering, landing. */
    void hover() {
        stage = TransitionState.HOVER;
        airspeed = 0;
    }

    /** Slowing down on its lift motors from forward flight: a VTOL landing's airbrake and position1. */
    void airbrake() {
        stage = TransitionState.AIRBRAKE;
    }

    boolean hovering() {
        return stage == TransitionState.HOVER;
    }

    /**
     * One step of forward flight of {@code dt} seconds, said on {@code craft}: from a hover (or an
     * airbrake) the transition starts; the speed it may fly at, which rises through the transition.
     */
    double forward(Craft craft, double dt) {
        switch (stage) {
            case HOVER, AIRBRAKE -> {
                craft.say(String.format(Locale.ROOT, "Transition started airspeed %.1f", airspeed));
                stage = TransitionState.AIRSPEED_WAIT;
            }
            case AIRSPEED_WAIT -> {
                airspeed += TRANSITION_ACCEL * dt;
                if (airspeed > ASSIST_SPEED) {
                    craft.say(String.format(Locale.ROOT, "Transition airspeed reached %.1f", airspeed));
                    stage = TransitionState.TIMER;
                    timer = 0;
                }
            }
            case TIMER -> {
                airspeed += TRANSITION_ACCEL * dt;
                timer += dt;
                if (timer > TRANSITION_SECONDS) {
                    craft.say("Transition done");
                    stage = TransitionState.WING;
                }
            }
            case WING -> {
                return Double.POSITIVE_INFINITY;
            }
        }
        return airspeed;
    }

    /** The speed it may fly forward at: unlimited on its wing, its airspeed so far in a transition. */
    double airspeed() {
        return stage == TransitionState.WING ? Double.POSITIVE_INFINITY : airspeed;
    }

    /** MAV_VTOL_STATE: MC hovering, TRANSITION_TO_FW, FW, TRANSITION_TO_MC in an airbrake. */
    int mavState() {
        return stage.mavState;
    }
}
