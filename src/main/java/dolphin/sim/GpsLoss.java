package dolphin.sim;

import com.MAVLink.enums.MAV_SEVERITY;

/**
 * The GPS receiver falls silent (SITL: SIM_GPS1_ENABLE 0) and what follows, on {@link FaultTable}'s
 * times: AP_GPS gives the receiver up (GPS_RAW_INT NO_GPS), EKF3's horizontal position times out
 * (EKF_STATUS_REPORT loses the position bits), the vehicle's ekf_check fails a second later and its
 * {@link EkfFailsafe} acts (ArduCopter: LAND after a pause, landing and disarming as LAND does), and
 * EKF3 stops aiding. The GPS never comes back; the failsafe stays on (the heartbeat says CRITICAL).
 */
final class GpsLoss implements Fault {

    private final EkfFailsafe failsafe;
    private double elapsed;
    private double pause;
    private Manoeuvre hold;

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
            FaultTable.STOPPED_AIDING.forEach(t -> vehicle.text(FaultTable.STOPPED_AIDING_SEVERITY, t));
            vehicle.navigation().ekfFlags(FaultTable.EKF_NOT_AIDING);
        }
        if (holdsFlight(vehicle)) {
            pause -= dt;
            hold.step(dt);
        }
        return true;
    }

    /** The failsafe's pause: it holds where it was, in the failsafe's mode, before it moves. */
    @Override
    public boolean holdsFlight(FaultHost vehicle) {
        return pause > 0 && vehicle.mode() == failsafe.mode();
    }

    private boolean reached(double before, double at) {
        return before < at && elapsed >= at;
    }

    /** ekf_check gives up on the position, and failsafe_ekf_event does what the firmware does. */
    private void check(FaultHost vehicle) {
        if (!vehicle.armed() && !failsafe.checksDisarmed()) {
            return;
        }
        vehicle.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, failsafe.varianceText());
        vehicle.navigation().failsafe(true);
        if (!vehicle.armed()) {
            return;
        }
        if (!failsafe.needsPosition().test(vehicle.mode())) {
            failsafe.noActionText().ifPresent(t -> vehicle.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL, t));
            return;
        }
        // ekf_check's text, then the mode change with its heartbeat, then the failsafe's text, as SITL sent them
        vehicle.flush();
        if (vehicle.setMode(failsafe.mode())) {
            pause = failsafe.pauseSeconds();
            hold = vehicle.firmware().holdAt(vehicle.craft(), vehicle.craft().position());
        }
        vehicle.text(MAV_SEVERITY.MAV_SEVERITY_CRITICAL,
                String.format(failsafe.actionText(), vehicle.firmware().family().modeName(vehicle.mode())));
    }
}
