package dolphin.sim;

/**
 * The autopilot reboots ({@link FaultHost#reboot}): the vehicle starts again as it booted, disarmed;
 * one in the air comes down without thrust ({@link Fall}) and lies where it lands.
 */
final class Reboot implements Fault {

    private final Fall fall = new Fall();

    @Override
    public void begin(FaultHost vehicle) {
        vehicle.reboot();
    }

    @Override
    public boolean step(FaultHost vehicle, double dt) {
        Craft craft = vehicle.craft();
        if (!craft.contact()) {
            fall.step(craft, dt);
            return true;
        }
        craft.settle();
        return false;
    }

    /** Until it is down: its motors stopped with the autopilot. */
    @Override
    public boolean holdsFlight(FaultHost vehicle) {
        return true;
    }
}
