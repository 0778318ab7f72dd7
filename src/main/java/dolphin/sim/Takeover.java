package dolphin.sim;

/**
 * A pilot on a second ground station takes the vehicle over: sets a mode as DO_SET_MODE would (the
 * heartbeat shows it; the answer goes to that station, not to ours), in which the vehicle holds
 * where it was, unless the mode flies it itself (RTL, LAND); after the duration, if the mode is still
 * the pilot's, sets AUTO again, so the mission resumes at its current item (AP_Mission::resume). A
 * mode someone else set meanwhile is left alone.
 */
final class Takeover implements Fault {

    private final int mode;
    private final double seconds;
    private double elapsed;
    private Manoeuvre hold;

    /** Mode {@code mode} for {@code seconds} of clock time. */
    Takeover(int mode, double seconds) {
        this.mode = mode;
        this.seconds = seconds;
    }

    @Override
    public void begin(FaultHost vehicle) {
        if (vehicle.setMode(mode)) {
            hold = vehicle.firmware().holdAt(vehicle.craft(), vehicle.craft().position());
        }
    }

    @Override
    public boolean step(FaultHost vehicle, double dt) {
        elapsed += dt;
        boolean held = vehicle.mode() == mode;
        if (held && hold != null && vehicle.armed() && !vehicle.flightMoves()) {
            hold.step(dt);
        }
        if (elapsed < seconds) {
            return true;
        }
        if (held) {
            vehicle.setMode(vehicle.firmware().autoMode());
        }
        return false;
    }
}
