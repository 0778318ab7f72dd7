package dolphin.sim;

/**
 * A vehicle that cannot reach its mission item, as against a wind it cannot beat: in AUTO it keeps
 * its mode and its current item but makes no progress, holding where it was when it met the wind
 * (a plane circling there), for the duration (infinite: for ever). Other modes (RTL, LAND, set by a
 * ground station) fly as usual.
 */
final class Stall implements Fault {

    private final double seconds;
    private double elapsed;
    private Manoeuvre hold;

    /** For {@code seconds} of clock time; infinite: for ever. */
    Stall(double seconds) {
        this.seconds = seconds;
    }

    @Override
    public void begin(FaultHost vehicle) {
        // the wind rises; it holds the vehicle from its next tick in AUTO
    }

    @Override
    public boolean step(FaultHost vehicle, double dt) {
        elapsed += dt;
        if (!holdsFlight(vehicle)) {
            hold = null;
        } else if (vehicle.armed()) {
            if (hold == null) {
                hold = vehicle.firmware().holdAt(vehicle.craft(), vehicle.craft().position());
            }
            hold.step(dt);
        }
        return elapsed < seconds;
    }

    @Override
    public boolean holdsFlight(FaultHost vehicle) {
        return vehicle.mode() == vehicle.firmware().autoMode();
    }
}
