package dolphin.sim;

import java.util.Locale;

/**
 * A copter's motor stops (SITL: SIM_ENGINE_MUL 0, SIM_ENGINE_FAIL): the copter cannot hold its height
 * in any mode, so it {@link Fall}s and hits the ground. There, armed, still in its mode and at its
 * mission item, its motors at full throttle and the land detector never satisfied (so
 * EXTENDED_SYS_STATE says IN_AIR, as GCS_MAVLINK_Copter::landed_state does without land_complete),
 * it says {@link FaultTable#THRUST_LOSS} at first after {@link FaultTable#THRUST_LOSS_FIRST} and
 * then every {@link FaultTable#THRUST_LOSS_REPEAT} seconds, until it is disarmed. The motor never
 * comes back.
 */
final class ThrustLoss extends PowerLoss {

    private final int motor;
    private final Fall fall = new Fall();
    private double untilText = FaultTable.THRUST_LOSS_FIRST;

    /** Motor {@code motor} (from 1) stops. */
    ThrustLoss(int motor) {
        this.motor = motor;
    }

    @Override
    void descend(Craft craft, double dt) {
        fall.step(craft, dt);
    }

    /** Copter::thrust_loss_check looks only while armed and not landed (a copter that never took off is landed). */
    @Override
    boolean grounded(FaultHost vehicle, double dt) {
        if (!vehicle.armed() || vehicle.craft().onGround()) {
            untilText = FaultTable.THRUST_LOSS_FIRST;
            return true;
        }
        untilText -= dt;
        if (untilText <= 0) {
            vehicle.text(FaultTable.THRUST_LOSS_SEVERITY, String.format(Locale.ROOT, FaultTable.THRUST_LOSS, motor));
            untilText += FaultTable.THRUST_LOSS_REPEAT;
        }
        return true;
    }
}
