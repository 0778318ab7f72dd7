package dolphin.sim;

import com.MAVLink.enums.MAV_SEVERITY;
import java.util.Optional;

/**
 * The GPS receiver falls silent (SITL: SIM_GPS1_ENABLE 0) and what follows, on {@link FaultTable}'s
 * times: AP_GPS gives the receiver up (GPS_RAW_INT NO_GPS), EKF3's horizontal position times out
 * (EKF_STATUS_REPORT loses the position bits), the vehicle's ekf_check fails a second later and its
 * {@link EkfFailsafe} acts (ArduCopter: EKF3's lane switch, then LAND after a pause, landing and
 * disarming as LAND does), EKF3 stops aiding, and SmartRTL gives up. The GPS never comes back; the
 * failsafe stays on (the heartbeat says CRITICAL).
 */
final class GpsLoss implements Fault {

    private final EkfFailsafe failsafe;
    private double elapsed;

    GpsLoss(EkfFailsafe failsafe) {
        this.failsafe = failsafe;
    }

    @Override
    public void begin(FaultHost vehicle) {
        // the receiver falls silent; AP_GPS and the EKF notice on their own timeouts
    }

    @Override
    public boolean step(FaultHost vehicle, double dt) {
        double before = elapsed;
        elapsed += dt;
        if (reached(before, FaultTable.GPS_TIMEOUT)) {
            vehicle.navigation().gpsLost();
        }
        if (reached(before, FaultTable.POSITION_TIMEOUT)) {
            vehicle.navigation().ekfFlags(FaultTable.EKF_POSITION_LOST);
        }
        if (reached(before, FaultTable.POSITION_TIMEOUT + FaultTable.EKF_CHECK)) {
            check(vehicle);
        }
        if (reached(before, FaultTable.AIDING_TIMEOUT)) {
            FaultTable.stoppedAiding(vehicle.navigation().primaryLane())
                    .forEach(t -> vehicle.text(FaultTable.STOPPED_AIDING_SEVERITY, t));
            vehicle.navigation().ekfFlags(FaultTable.EKF_NOT_AIDING);
        }
        if (reached(before, failsafe.smartRtlOff()) && vehicle.armed()) {
            vehicle.text(FaultTable.SMART_RTL_OFF_SEVERITY, FaultTable.SMART_RTL_OFF);
        }
        return true;
    }

    private boolean reached(double before, double at) {
        return before < at && elapsed >= at;
    }

    /** ekf_check gives up on the position, and failsafe_ekf_event does what the firmware does. */
    private void check(FaultHost vehicle) {
        if (!vehicle.armed() && !failsafe.checksDisarmed()) {
            return;
        }
        vehicle.navigation().failsafe(true);
        if (!vehicle.armed()) {
            vehicle.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, failsafe.varianceText());
            return;
        }
        if (failsafe.laneSwitch()) {
            vehicle.laneSwitch(1);
        }
        boolean acts = failsafe.needsPosition().test(vehicle.mode());
        if (acts) {
            // the lane switch's texts, then the new mode's heartbeat, then ekf_check's texts, as SITL sent them
            vehicle.flush();
            if (vehicle.setMode(failsafe.mode())) {
                vehicle.pauseFlight(failsafe.pauseSeconds());
            }
        }
        vehicle.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, failsafe.varianceText());
        Optional<String> then = acts ? Optional.of(failsafe.actionText()) : failsafe.noActionText();
        then.ifPresent(t -> vehicle.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, t));
    }
}
