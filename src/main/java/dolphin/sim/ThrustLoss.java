package dolphin.sim;

import java.util.Locale;

/**
 * A copter's motor stops (SITL: SIM_ENGINE_MUL 0, SIM_ENGINE_FAIL with the motor's bit): the copter
 * cannot hold its height in any mode, so it {@link Fall}s and hits the ground, where the shock makes
 * EKF3 switch to lane 1 and, {@link FaultTable#LANE_SWITCH_BACK} later, back to lane 0. There, armed,
 * still in its mode and at its mission item, its motors at full throttle and the land detector never
 * satisfied (so EXTENDED_SYS_STATE says IN_AIR, as GCS_MAVLINK_Copter::landed_state does without
 * land_complete), it says {@link FaultTable#THRUST_LOSS}, naming the motor ArduCopter takes for lost,
 * {@link FaultTable#THRUST_LOSS_FIRST} after the hit and then every {@link FaultTable#THRUST_LOSS_REPEAT}
 * seconds, until it is disarmed. The motor never comes back.
 */
final class ThrustLoss extends PowerLoss {

    private final int named;
    private final Fall fall = new Fall();
    private double untilText = FaultTable.THRUST_LOSS_FIRST;
    /** Seconds since the first hit after a fall; negative before it (a motor stopped on the ground makes no hit). */
    private double sinceHit = -1;
    private boolean fell;

    /** Motor {@code motor} (from 1) stops. */
    ThrustLoss(int motor) {
        this.named = FaultTable.THRUST_LOSS_NAMED.getOrDefault(motor, motor);
    }

    @Override
    void descend(Craft craft, double dt) {
        fell = true;
        fall.step(craft, dt);
    }

    /** Copter::thrust_loss_check looks only while armed and not landed (a copter that never took off is landed). */
    @Override
    boolean grounded(FaultHost vehicle, double dt) {
        shaken(vehicle, dt);
        if (!vehicle.armed() || vehicle.craft().onGround()) {
            untilText = FaultTable.THRUST_LOSS_FIRST;
            return true;
        }
        untilText -= dt;
        if (untilText <= 0) {
            vehicle.text(FaultTable.THRUST_LOSS_SEVERITY, String.format(Locale.ROOT, FaultTable.THRUST_LOSS, named));
            untilText += FaultTable.THRUST_LOSS_REPEAT;
        }
        return true;
    }

    /** EKF3's lane switches after the hit: to lane 1 at once, back to lane 0 a moment later; armed only, as its core selection. */
    private void shaken(FaultHost vehicle, double dt) {
        if (!fell) {
            return;
        }
        boolean first = sinceHit < 0;
        double before = sinceHit;
        sinceHit = first ? 0 : sinceHit + dt;
        if (!vehicle.armed()) {
            return;
        }
        if (first) {
            vehicle.laneSwitch(1);
        } else if (before < FaultTable.LANE_SWITCH_BACK && sinceHit >= FaultTable.LANE_SWITCH_BACK) {
            vehicle.laneSwitch(0);
        }
    }
}
