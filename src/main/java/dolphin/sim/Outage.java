package dolphin.sim;

/**
 * The radio link fails for a while: the vehicle sends nothing and hears nothing, and goes on flying
 * as it was (ArduPilot's GCS failsafe, FS_GCS_ENABLE, is off by default), then is heard again.
 */
final class Outage implements Fault {

    private final double seconds;
    private double elapsed;

    /** For {@code seconds} of clock time. */
    Outage(double seconds) {
        this.seconds = seconds;
    }

    @Override
    public void begin(FaultHost vehicle) {
        vehicle.cutOff(true);
    }

    @Override
    public boolean step(FaultHost vehicle, double dt) {
        elapsed += dt;
        if (elapsed < seconds) {
            return true;
        }
        vehicle.cutOff(false);
        return false;
    }
}
