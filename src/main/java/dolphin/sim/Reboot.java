package dolphin.sim;

/**
 * The autopilot reboots ({@link FaultHost#reboot}): the vehicle starts again as it booted, disarmed;
 * its motors stopped, one in the air comes down ({@link Fall}) and lies where it lands.
 */
final class Reboot extends PowerLoss {

    private final Fall fall = new Fall();

    @Override
    public void begin(FaultHost vehicle) {
        vehicle.reboot();
    }

    @Override
    void descend(Craft craft, double dt) {
        fall.step(craft, dt);
    }

    /** Down: it is over. */
    @Override
    boolean grounded(FaultHost vehicle, double dt) {
        vehicle.craft().settle();
        return false;
    }
}
